// Image error metrics. All are computed on display values: 8-bit sRGB after tonemapping, scaled to
// [0, 1] — what a player sees, and the space the post filters work in.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

namespace app {

// An RGB image of display values in [0, 1], top-down.
struct DisplayImage {
  int width = 0, height = 0;
  std::vector<float> rgb;
  static DisplayImage fromRgba8(int width, int height, const std::vector<uint8_t>& rgba);
  float luma(int x, int y) const;  // Rec. 709 weights on display values
};

struct ErrorMetrics {
  double mse = 0;      // mean over pixels and RGB channels
  double psnrDb = 0;   // 10 log10(1 / mse); capped at kPsnrCapDb for identical images
  double edgeMse = 0;  // the same over the edge mask only
  double edgePsnrDb = 0;
  double interiorMse = 0;  // the same off the edge mask (every pixel when the mask is empty): blur shows here
  double interiorPsnrDb = 0;
  double ssim = 0;         // Wang et al. 2004 on luma: 11×11 Gaussian window, σ = 1.5
  double maxAbsError = 0;  // largest per-channel difference
  int edgePixels = 0;
  int interiorPixels = 0;
};

constexpr double kPsnrCapDb = 100.0;

double psnrFromMse(double mse);
// `edgeMask` (one byte per pixel, non-zero = edge) may be empty: edge figures are then 0.
ErrorMetrics compare(const DisplayImage& image, const DisplayImage& reference, const std::vector<uint8_t>& edgeMask);
// The same without the SSIM (left 0): the per-pixel figures alone, for a mask that is not the edges.
ErrorMetrics pixelErrors(const DisplayImage& image, const DisplayImage& reference,
                         const std::vector<uint8_t>& edgeMask);
double ssim(const DisplayImage& a, const DisplayImage& b);

// A method's error over consecutive frames of one sequence, added in order.
class SequenceError {
 public:
  // `changed`: the pixels whose reference changed since the frame before (empty: none known).
  void add(const DisplayImage& image, const DisplayImage& reference, const std::vector<uint8_t>& changed);
  // Mean over consecutive pairs of the RMS change of the signed error: shimmer and swings the reference
  // does not have. 0 with one frame.
  double flicker() const { return flickerPairs_ ? flickerSum_ / flickerPairs_ : 0.0; }
  // Mean PSNR over the changed pixels of the frames that have any: a history's lag shows there.
  std::optional<double> lagPsnrDb() const;

 private:
  std::vector<float> previousError_;  // signed display error of the frame before
  double flickerSum_ = 0, lagSum_ = 0;
  int flickerPairs_ = 0, lagFrames_ = 0;
};

// Edge pixels of the ground truth: where its supersamples' display luma spread exceeds `threshold`.
std::vector<uint8_t> edgeMaskFromSpread(const std::vector<float>& lumaStdDev, float threshold = 0.03f);
// The models' and scene's edges: those of `withoutBackgroundDetail` (the spread with the stars off) except
// where the background's detail changes the spread (a star behind a silhouette would be measured too).
std::vector<uint8_t> modelEdgeMask(const std::vector<float>& lumaStdDev,
                                   const std::vector<float>& withoutBackgroundDetail);

// Per-pixel error magnitude as a heat map (black → red → yellow → white), RGBA8 top-down; `scale`
// maps an absolute error to the top of the colour ramp.
std::vector<uint8_t> errorHeatmap(const DisplayImage& image, const DisplayImage& reference, float scale = 0.25f);

}  // namespace app
