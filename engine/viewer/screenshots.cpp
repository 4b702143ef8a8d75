// Screenshots of the view and of the window (see screenshots.hpp).
#include "screenshots.hpp"

#include "core/image_io.hpp"
#include "view_render_thread.hpp"

#include <algorithm>
#include <ctime>
#include <vector>

namespace rmsc::app {

bool writeViewShot(ViewRenderThread& renderer, const ViewInput& view, const Rect& viewport,
                   const Window& window, const std::string& path, std::string& error) {
    int ww = 0, wh = 0, fw = 0, fh = 0;
    window.windowSize(ww, wh);
    window.framebufferSize(fw, fh);
    const int w = std::max(1, int(viewport.width * float(fw) / float(std::max(ww, 1))));
    const int h = std::max(1, int(viewport.height * float(fh) / float(std::max(wh, 1))));
    const std::optional<Pixels<std::uint8_t>> image = renderer.capture(view, w, h, error);
    return image && writePng8(path, *image, error);
}

bool writeWindowShot(const Window& window, const std::string& path, std::string& error) {
    int fw = 0, fh = 0;
    window.framebufferSize(fw, fh);
    Pixels<std::uint8_t> image;
    image.width = fw;
    image.height = fh;
    image.channels = 4;
    image.data.resize(std::size_t(fw) * std::size_t(fh) * 4);
    std::vector<std::uint8_t> rows(image.data.size());
    {
        std::lock_guard submitting(glSubmissionMutex());
        glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
        glReadBuffer(GL_BACK);
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        glReadPixels(0, 0, fw, fh, GL_RGBA, GL_UNSIGNED_BYTE, rows.data());
    }
    for (int y = 0; y < fh; ++y) // GL reads bottom row first; images store the top row first
        std::copy_n(rows.data() + std::size_t(fh - 1 - y) * std::size_t(fw) * 4,
                    std::size_t(fw) * 4, image.data.data() + std::size_t(y) * std::size_t(fw) * 4);
    return writePng8(path, image, error);
}

std::filesystem::path defaultScreenshotPath(const std::filesystem::path& sceneFile) {
    char stamp[32];
    const std::time_t t = std::time(nullptr);
    std::strftime(stamp, sizeof(stamp), "%Y%m%d-%H%M%S", std::localtime(&t));
    const std::filesystem::path folder =
        sceneFile.empty() ? std::filesystem::current_path() : sceneFile.parent_path();
    return folder / ("rmsc-screenshot-" + std::string(stamp) + ".png");
}

} // namespace rmsc::app
