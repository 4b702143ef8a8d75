// A cell's postfix list in entries of two words (SdfListReading::PostfixPairs, sdf/program.hpp):
// an instruction, and the combine that follows it. The Cells shader's loop (common/
// sdf_interpreter.glsl) runs one entry a step, and on llvmpipe every step runs the code of every
// branch, taken by a pixel or not: a step that ran a shape or a combine ran both. In pairs, each
// step runs the shape's code and then a combine's, so a shape and the blend after it take one
// step where they took two (the 4,096-sphere tree's lists, two spheres and their blend, take two
// steps instead of three) and no step is a combine alone but one that follows another.
#include "sdf/program.hpp"

#include <algorithm>
#include <cassert>

namespace rmsc {

static_assert(limits::kSdfInstructions < (1 << kSdfFusedIndexBits) / 2,
              "a fused combine's index (and the pruning's added instructions) below 2^24");

namespace {
bool isCombine(const GpuSdfInstruction& in) {
    return SdfOpcode(in.opcode) == SdfOpcode::Combine;
}
} // namespace

void sdfPairList(std::span<const GpuSdfInstruction> code, std::span<const std::uint32_t> list,
                 std::vector<std::uint32_t>& out) {
    const bool skips = std::any_of(list.begin(), list.end(), [&](std::uint32_t i) {
        return SdfOpcode(code[i].opcode) == SdfOpcode::BoundSkip;
    });
    const std::size_t first = out.size();
    for (std::uint32_t i : list) {
        assert(i < (1u << kSdfFusedIndexBits));
        if (!isCombine(code[i])) {
            out.insert(out.end(), {i, kSdfNoFusedCombine});
            continue;
        }
        assert(code[i].kind < 255); // (SdfOp: a byte)
        const std::uint32_t fused = sdfFusedCombine(i, code[i].kind);
        if (!skips && out.size() > first && out.back() == kSdfNoFusedCombine)
            out.back() = fused;
        else // its own entry, the combine itself in the first word (which runs nothing)
            out.insert(out.end(), {i, fused});
    }
}

void sdfListInstructions(std::span<const GpuSdfInstruction> code,
                         std::span<const std::uint32_t> words, SdfListReading reading,
                         std::vector<std::uint32_t>& out) {
    if (reading != SdfListReading::PostfixPairs) {
        out.insert(out.end(), words.begin(), words.end());
        return;
    }
    assert(words.size() % 2 == 0);
    for (std::size_t n = 0; n + 1 < words.size(); n += 2) {
        if (!isCombine(code[words[n]])) out.push_back(words[n]);
        if (words[n + 1] != kSdfNoFusedCombine) out.push_back(sdfFusedIndex(words[n + 1]));
    }
}

} // namespace rmsc
