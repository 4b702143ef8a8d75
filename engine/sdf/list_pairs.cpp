// A cell's postfix list in entries of two words (SdfListReading::PostfixPairs, sdf/program.hpp):
// an instruction, and the combine that follows it, held whole. The Cells shader's loop (common/
// sdf_interpreter.glsl) runs one entry a step, and on llvmpipe every step runs the code of every
// branch, taken by a pixel or not: a step that ran a shape or a combine ran both. In pairs, each
// step runs the shape's code and then a combine's, so a shape and the blend after it take one
// step where they took two (the 4,096-sphere tree's lists, two spheres and their blend, take two
// steps instead of three). The combine's numbers are in the entry: a texel read inside the
// combine's branch cost the tree more than the steps saved (docs/performance.md).
#include "sdf/program.hpp"

#include <algorithm>
#include <cassert>
#include <cstring>

namespace rmsc {

static_assert(limits::kSdfInstructions < (1 << kSdfEntryIndexBits) / 2,
              "instruction indices (and the pruning's added instructions) below 2^24");

namespace {

bool isCombine(const GpuSdfInstruction& in) {
    return SdfOpcode(in.opcode) == SdfOpcode::Combine;
}

// sdfEntryCombine's code of a combine: 1 + 2 SdfOp + its curve (SmoothBlend, params[0].y: the
// shader's sdfSmoothMin takes 0.5 and up as circular).
std::uint32_t combineCode(const GpuSdfInstruction& in) {
    assert(in.kind < 127); // (SdfOp: the code in a byte)
    return 1 + 2 * in.kind + (in.params[0].y >= 0.5f ? 1 : 0);
}

std::uint32_t floatBits(float v) {
    std::uint32_t bits;
    std::memcpy(&bits, &v, sizeof bits);
    return bits;
}

} // namespace

void sdfPairList(std::span<const GpuSdfInstruction> code, std::span<const std::uint32_t> list,
                 std::vector<std::uint32_t>& out) {
    const bool skips = std::any_of(list.begin(), list.end(), [&](std::uint32_t i) {
        return SdfOpcode(code[i].opcode) == SdfOpcode::BoundSkip;
    });
    const std::size_t first = out.size();
    for (std::uint32_t i : list) {
        assert(i < (1u << kSdfEntryIndexBits));
        if (!isCombine(code[i])) {
            out.insert(out.end(), {i, 0u});
            continue;
        }
        const std::uint32_t combine = combineCode(code[i]) << kSdfEntryIndexBits;
        const std::uint32_t smoothness = floatBits(code[i].params[0].x);
        if (!skips && out.size() > first && sdfEntryCombine(out[out.size() - 2]) == 0) {
            out[out.size() - 2] |= combine;
            out.back() = smoothness;
        } else { // its own entry, the combine itself the instruction (which runs nothing)
            out.insert(out.end(), {i | combine, smoothness});
        }
    }
}

void sdfListProgram(std::span<const GpuSdfInstruction> code, std::span<const std::uint32_t> words,
                    SdfListReading reading, std::vector<GpuSdfInstruction>& out) {
    if (reading != SdfListReading::PostfixPairs) {
        for (std::uint32_t i : words)
            out.push_back(code[i]);
        return;
    }
    assert(words.size() % 2 == 0);
    for (std::size_t n = 0; n + 1 < words.size(); n += 2) {
        const GpuSdfInstruction& in = code[sdfEntryIndex(words[n])];
        if (!isCombine(in)) out.push_back(in);
        if (const std::uint32_t c = sdfEntryCombine(words[n]); c != 0) {
            GpuSdfInstruction combine;
            combine.opcode = std::uint32_t(SdfOpcode::Combine);
            combine.kind = (c - 1) / 2;
            float smoothness;
            std::memcpy(&smoothness, &words[n + 1], sizeof smoothness);
            combine.params[0] = glm::vec4(smoothness, float((c - 1) % 2), 0.0f, 0.0f);
            out.push_back(combine);
        }
    }
}

std::size_t sdfListInstructionCount(std::span<const GpuSdfInstruction> code,
                                    std::span<const std::uint32_t> words, SdfListReading reading) {
    if (reading != SdfListReading::PostfixPairs) return words.size();
    std::size_t count = 0;
    for (std::size_t n = 0; n + 1 < words.size(); n += 2)
        count += std::size_t(!isCombine(code[sdfEntryIndex(words[n])])) +
                 std::size_t(sdfEntryCombine(words[n]) != 0);
    return count;
}

int sdfListStackDepth(std::span<const GpuSdfInstruction> code, std::span<const std::uint32_t> words,
                      SdfListReading reading) {
    if (reading == SdfListReading::LeastOfShapes) return 0;
    const bool pairs = reading == SdfListReading::PostfixPairs;
    int top = 0, most = 0;
    for (std::size_t n = 0; n < words.size(); n += pairs ? 2 : 1) {
        const SdfOpcode opcode = SdfOpcode(code[pairs ? sdfEntryIndex(words[n]) : words[n]].opcode);
        if (opcode == SdfOpcode::Shape || opcode == SdfOpcode::Profile)
            most = std::max(most, ++top);
        else if (opcode == SdfOpcode::Accumulate || (!pairs && opcode == SdfOpcode::Combine))
            --top;
        if (pairs && sdfEntryCombine(words[n]) != 0) --top;
    }
    return most;
}

int sdfListPointStackDepth(std::span<const GpuSdfInstruction> code,
                           std::span<const std::uint32_t> words, SdfListReading reading) {
    const bool pairs = reading == SdfListReading::PostfixPairs;
    int top = 0, most = 0;
    for (std::size_t n = 0; n < words.size(); n += pairs ? 2 : 1) {
        const SdfOpcode opcode = SdfOpcode(code[pairs ? sdfEntryIndex(words[n]) : words[n]].opcode);
        if (opcode == SdfOpcode::PushPoint)
            most = std::max(most, ++top);
        else if (opcode == SdfOpcode::PopPoint)
            --top;
    }
    return most;
}

} // namespace rmsc
