// Ground truth: the host's stock pipeline rendered at s×s jittered sub-pixel positions, every
// supersample lit, box-filtered.
//
// Averaging happens on linear radiance, before tonemapping: a pixel's true value is the integral
// of the radiance over its footprint, and the slice methods composite their weighted lighting in the
// same linear space before the host's tonemap. (Averaging after tonemapping would instead model
// per-sample tonemapped resolves; at high-contrast silhouettes the two differ by up to the tonemap's
// curvature, which is why the choice is fixed here once.)
#pragma once

#include "engine.h"

#include <cstdint>
#include <vector>

namespace host {

struct GroundTruth {
  int width = 0, height = 0, samplesPerAxis = 0;
  std::vector<uint8_t> display;   // RGBA8 top-down, tonemapped average radiance
  std::vector<float> radiance;    // RGBA32F top-down, average linear radiance
  std::vector<float> lumaStdDev;  // per pixel: std. deviation of the supersamples' display luma (the scene without its
                                  // material maps: geometry and lighting edges, not texture detail)
  // The same spread without the background's own detail (stars): the models' and the scene's edges alone.
  // Empty unless asked for (BackgroundEdges::Apart) and the engine's background has detail.
  std::vector<float> modelLumaStdDev;
};

// Whether the ground truth also measures its spread without the background's detail (s² frames more).
enum class BackgroundEdges { Together, Apart };

// How each supersample filters the material textures: over its own footprint, 1/s of a pixel (a
// texture LOD bias of −log2 s, as a render s× larger would), or over the whole pixel's (no bias: the
// textures come out over-blurred; kept to show what the bias is for).
enum class TextureFootprint { Supersample, Pixel };

// Renders with the host's stock path (the caller takes its AA hooks off first, or the ground truth
// holds the AA's images).
GroundTruth renderGroundTruth(Engine& engine, const Camera& camera, int samplesPerAxis,
                              TextureFootprint footprint = TextureFootprint::Supersample,
                              BackgroundEdges backgroundEdges = BackgroundEdges::Together);

}  // namespace host
