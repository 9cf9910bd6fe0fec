// What `smaa-s2x` computes on the CPU from the driver's sample positions (defined in smaa.cpp; the
// tests check them against the reference's values).
#pragma once
#include <array>
#include <vector>

namespace retroaa {

// SMAA's subsample indices for a sample at (x, y) in its pixel ([0, 1)², the driver's position): the
// area-texture rows of its orthogonal offsets along x and y and of its diagonal offset.
// The reference's S2x samples at D3D's (+¼, +¼) and (−¼, −¼) read rows (1, 1, 1, 0) and (2, 2, 2, 0).
std::array<float, 4> smaaSubsampleIndices(float x, float y);
// The two samples S2x lights, from the driver's positions (x, y pairs): the pair whose midpoint is
// nearest the pixel centre (their average must not shift the image), the farther apart on a tie, the
// lowest indices after that. 2×: samples 0 and 1; llvmpipe's 4× (0.375, 0.125) … : samples 0 and 3.
std::array<int, 2> smaaS2xSamplePair(const std::vector<float>& positionsXY);

}  // namespace retroaa
