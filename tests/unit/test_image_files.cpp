// Image outputs (core/image_io.hpp) are complete or not written at all: when the disk refuses
// bytes (simulated by the file size limit, RLIMIT_FSIZE, which fails writes with EFBIG as a
// full disk fails them with ENOSPC) the save fails with a reason, the previous file is kept and
// no temporary file is left; otherwise the file reads back exactly.
#include "core/image_io.hpp"

#include "temp_folder.hpp"

#include <gtest/gtest.h>

#include <csignal>
#include <cstring>
#include <fstream>
#include <functional>
#include <random>
#include <sstream>
#include <sys/resource.h>
#include <unistd.h>

using namespace rmsc;
namespace fs = std::filesystem;

namespace {

class ImageFiles : public test::TempFolderTest {
  protected:
    std::size_t filesInFolder() const {
        return std::size_t(std::distance(fs::directory_iterator(folder_), {}));
    }
};

// Noise does not compress: its PNG is far larger than the limit below.
template <class T> Pixels<T> noise(int width, int height, int channels, unsigned maxValue) {
    Pixels<T> image{width, height, channels, {}};
    std::mt19937 rng(5);
    image.data.resize(std::size_t(width) * height * channels);
    for (T& v : image.data)
        v = T(rng() % (maxValue + 1));
    return image;
}

// While alive, files may grow to `bytes` at most (writes past it fail with EFBIG, not SIGXFSZ).
struct FileSizeLimit {
    explicit FileSizeLimit(rlim_t bytes) {
        previousHandler = std::signal(SIGXFSZ, SIG_IGN);
        getrlimit(RLIMIT_FSIZE, &previous);
        rlimit limited = previous;
        limited.rlim_cur = bytes;
        EXPECT_EQ(setrlimit(RLIMIT_FSIZE, &limited), 0);
    }
    ~FileSizeLimit() {
        setrlimit(RLIMIT_FSIZE, &previous);
        std::signal(SIGXFSZ, previousHandler);
    }
    rlimit previous{};
    void (*previousHandler)(int) = nullptr;
};

} // namespace

TEST_F(ImageFiles, AFullDiskFailsEveryOutputAndKeepsThePreviousFile) {
    const auto rgb8 = noise<std::uint8_t>(128, 128, 3, 255);
    const auto grey16 = noise<std::uint16_t>(128, 128, 1, 65535);
    const auto floats = noise<float>(64, 64, 3, 1000);
    struct Output {
        const char* name;
        std::function<bool(const fs::path&, std::string&)> write;
    };
    const Output outputs[] = {
        {"color.png", [&](const fs::path& p, std::string& e) { return writePng8(p, rgb8, e); }},
        {"depth.png", [&](const fs::path& p, std::string& e) { return writePng16(p, grey16, e); }},
        {"normal.pfm", [&](const fs::path& p, std::string& e) { return writePfm(p, floats, e); }},
    };
    for (const Output& output : outputs) {
        SCOPED_TRACE(output.name);
        const fs::path path = folder_ / output.name;
        std::ofstream(path, std::ios::binary) << "previous image";
        const std::size_t before = filesInFolder();
        std::string error;
        bool written = false;
        {
            FileSizeLimit limit(4096);
            written = output.write(path, error);
        }
        EXPECT_FALSE(written) << "a write the disk refused must not report success";
        EXPECT_NE(error.find(path.parent_path().string()), std::string::npos) << error;
        EXPECT_EQ(read(path), "previous image");
        EXPECT_EQ(filesInFolder(), before) << "no temporary file may be left behind";
    }
}

TEST_F(ImageFiles, OutputsReadBackExactly) {
    const auto rgba8 = noise<std::uint8_t>(37, 21, 4, 255);
    std::string error;
    ASSERT_TRUE(writePng8(folder_ / "a.png", rgba8, error)) << error;
    const std::optional<Pixels<std::uint8_t>> back = readPng8(folder_ / "a.png", 4, error);
    ASSERT_TRUE(back) << error;
    EXPECT_EQ(back->width, 37);
    EXPECT_EQ(back->height, 21);
    EXPECT_EQ(back->data, rgba8.data);

    const auto floats = noise<float>(5, 3, 1, 1000);
    ASSERT_TRUE(writePfm(folder_ / "a.pfm", floats, error)) << error;
    const std::string pfm = read(folder_ / "a.pfm");
    const std::string header = "Pf\n5 3\n-1.0\n";
    ASSERT_EQ(pfm.size(), header.size() + floats.data.size() * sizeof(float));
    EXPECT_EQ(pfm.substr(0, header.size()), header);
    // Bottom row first.
    float firstOfLastRow = 0.0f;
    std::memcpy(&firstOfLastRow, pfm.data() + header.size(), sizeof(float));
    EXPECT_EQ(firstOfLastRow, *floats.at(0, 2));

    const auto grey16 = noise<std::uint16_t>(9, 4, 1, 65535);
    ASSERT_TRUE(writePng16(folder_ / "d.png", grey16, error)) << error;
    const std::string png = read(folder_ / "d.png");
    EXPECT_EQ(png.substr(1, 3), "PNG");
    EXPECT_NE(png.find("IEND"), std::string::npos);
}
