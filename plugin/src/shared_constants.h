// The numbers C++ and GLSL must agree on: texture units, enum values, limits. The shader library
// prepends every one as `#define NAME value` to every program it builds, so no shader numbers them
// by hand and a renumbered enum reaches the shaders by itself.
#pragma once

#include <string>

namespace retroaa {

// Texture units with a fixed meaning across passes. G-buffer attachment i is bound to unit i (≤ 8).
constexpr int kUnitSliceCounts = 13;  // the slice counts, for the depth writes of the slices (DepthSource::DepthBuffer)
constexpr int kUnitSliceWeights = 14;  // a technique's per-pixel input to the slice composite
constexpr int kUnitDepthStencil = 15;  // the MSAA G-buffer's depth-stencil
constexpr int kMaxAttachments = 8;     // host G-buffer attachments (units 0..7; a layout may have no more)
constexpr unsigned kNoSlice = 7u;      // a sample no slice lights (slice assignments: 3 bits per sample)

// "#define NAME value\n" for every shared constant and every enum value a shader compares against
// (WEIGHTING_*, DETECTOR_*, DEPTH_BUFFER_*, DEPTH_SOURCE_*, NORMAL_*), generated from the C++ enums themselves.
const std::string& sharedConstantDefines();

// "#define NAME value\n".
std::string defineLine(const char* name, long long value);

}  // namespace retroaa
