#include "metrics.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace app {

DisplayImage DisplayImage::fromRgba8(int width, int height, const std::vector<uint8_t>& rgba) {
  DisplayImage image;
  image.width = width;
  image.height = height;
  image.rgb.resize(size_t(width) * height * 3);
  for (size_t p = 0; p < size_t(width) * height; ++p)
    for (int c = 0; c < 3; ++c) image.rgb[p * 3 + c] = rgba[p * 4 + c] / 255.0f;
  return image;
}

float DisplayImage::luma(int x, int y) const {
  const float* p = &rgb[(size_t(y) * width + x) * 3];
  return 0.2126f * p[0] + 0.7152f * p[1] + 0.0722f * p[2];
}

double psnrFromMse(double mse) { return mse <= 0 ? kPsnrCapDb : std::min(kPsnrCapDb, 10.0 * std::log10(1.0 / mse)); }

ErrorMetrics pixelErrors(const DisplayImage& image, const DisplayImage& reference,
                         const std::vector<uint8_t>& edgeMask) {
  if (image.width != reference.width || image.height != reference.height)
    throw std::invalid_argument("compare: image sizes differ");
  ErrorMetrics m;
  double sum = 0, edgeSum = 0, interiorSum = 0;
  const size_t pixels = size_t(image.width) * image.height;
  for (size_t p = 0; p < pixels; ++p) {
    double pixelSum = 0;
    for (int c = 0; c < 3; ++c) {
      const double d = double(image.rgb[p * 3 + c]) - reference.rgb[p * 3 + c];
      pixelSum += d * d;
      m.maxAbsError = std::max(m.maxAbsError, std::fabs(d));
    }
    sum += pixelSum;
    if (!edgeMask.empty() && edgeMask[p]) {
      edgeSum += pixelSum;
      ++m.edgePixels;
    } else {
      interiorSum += pixelSum;
      ++m.interiorPixels;
    }
  }
  m.mse = sum / (3.0 * pixels);
  m.psnrDb = psnrFromMse(m.mse);
  if (m.edgePixels > 0) {
    m.edgeMse = edgeSum / (3.0 * m.edgePixels);
    m.edgePsnrDb = psnrFromMse(m.edgeMse);
  }
  if (m.interiorPixels > 0) {
    m.interiorMse = interiorSum / (3.0 * m.interiorPixels);
    m.interiorPsnrDb = psnrFromMse(m.interiorMse);
  }
  return m;
}

ErrorMetrics compare(const DisplayImage& image, const DisplayImage& reference, const std::vector<uint8_t>& edgeMask) {
  ErrorMetrics m = pixelErrors(image, reference, edgeMask);
  m.ssim = ssim(image, reference);
  return m;
}

double ssim(const DisplayImage& a, const DisplayImage& b) {
  // Wang, Bovik, Sheikh, Simoncelli 2004: K1 = 0.01, K2 = 0.03, L = 1, 11×11 Gaussian σ = 1.5,
  // windows fully inside the image, mean over windows.
  constexpr int radius = 5;
  constexpr double c1 = 0.01 * 0.01, c2 = 0.03 * 0.03;
  double kernel[2 * radius + 1], kernelSum = 0;
  for (int i = -radius; i <= radius; ++i) kernelSum += kernel[i + radius] = std::exp(-(i * i) / (2.0 * 1.5 * 1.5));
  for (double& k : kernel) k /= kernelSum;
  const int w = a.width, h = a.height;
  if (w <= 2 * radius || h <= 2 * radius) throw std::invalid_argument("ssim: image smaller than its 11×11 window");
  // Separable filtering of x, y, x², y², xy.
  std::vector<double> planes[5], rows[5];
  for (auto& p : planes) p.assign(size_t(w) * h, 0.0);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const double va = a.luma(x, y), vb = b.luma(x, y);
      const size_t i = size_t(y) * w + x;
      planes[0][i] = va, planes[1][i] = vb, planes[2][i] = va * va, planes[3][i] = vb * vb, planes[4][i] = va * vb;
    }
  for (int k = 0; k < 5; ++k) {
    rows[k].assign(size_t(w) * h, 0.0);
    for (int y = 0; y < h; ++y)
      for (int x = radius; x < w - radius; ++x) {
        double s = 0;
        for (int i = -radius; i <= radius; ++i) s += kernel[i + radius] * planes[k][size_t(y) * w + x + i];
        rows[k][size_t(y) * w + x] = s;
      }
  }
  double total = 0;
  long count = 0;
  for (int y = radius; y < h - radius; ++y)
    for (int x = radius; x < w - radius; ++x) {
      double m[5];
      for (int k = 0; k < 5; ++k) {
        double s = 0;
        for (int i = -radius; i <= radius; ++i) s += kernel[i + radius] * rows[k][size_t(y + i) * w + x];
        m[k] = s;
      }
      const double varA = m[2] - m[0] * m[0], varB = m[3] - m[1] * m[1], cov = m[4] - m[0] * m[1];
      total += ((2 * m[0] * m[1] + c1) * (2 * cov + c2)) / ((m[0] * m[0] + m[1] * m[1] + c1) * (varA + varB + c2));
      ++count;
    }
  return total / count;
}

std::vector<uint8_t> edgeMaskFromSpread(const std::vector<float>& lumaStdDev, float threshold) {
  std::vector<uint8_t> mask(lumaStdDev.size());
  for (size_t i = 0; i < mask.size(); ++i) mask[i] = lumaStdDev[i] > threshold ? 1 : 0;
  return mask;
}

std::vector<uint8_t> modelEdgeMask(const std::vector<float>& lumaStdDev,
                                   const std::vector<float>& withoutBackgroundDetail) {
  // Where the background has no detail, both spreads come from the same samples of the same frame: equal
  // to the bit. A faint star behind an edge changes it by more than this.
  constexpr float kBackgroundDetailSpread = 1.0f / 512.0f;
  std::vector<uint8_t> mask = edgeMaskFromSpread(withoutBackgroundDetail);
  for (size_t i = 0; i < mask.size(); ++i)
    if (std::fabs(lumaStdDev[i] - withoutBackgroundDetail[i]) > kBackgroundDetailSpread) mask[i] = 0;
  return mask;
}

std::vector<uint8_t> errorHeatmap(const DisplayImage& image, const DisplayImage& reference, float scale) {
  std::vector<uint8_t> out(size_t(image.width) * image.height * 4);
  for (size_t p = 0; p < size_t(image.width) * image.height; ++p) {
    float e = 0;
    for (int c = 0; c < 3; ++c) e = std::max(e, std::fabs(image.rgb[p * 3 + c] - reference.rgb[p * 3 + c]));
    const float t = std::clamp(e / scale, 0.0f, 1.0f) * 3.0f;  // black → red → yellow → white
    out[p * 4 + 0] = uint8_t(255 * std::clamp(t, 0.0f, 1.0f));
    out[p * 4 + 1] = uint8_t(255 * std::clamp(t - 1.0f, 0.0f, 1.0f));
    out[p * 4 + 2] = uint8_t(255 * std::clamp(t - 2.0f, 0.0f, 1.0f));
    out[p * 4 + 3] = 255;
  }
  return out;
}

void SequenceError::add(const DisplayImage& image, const DisplayImage& reference, const std::vector<uint8_t>& changed) {
  if (std::count(changed.begin(), changed.end(), 1) > 0)
    lagSum_ += pixelErrors(image, reference, changed).edgePsnrDb, ++lagFrames_;
  std::vector<float> error(image.rgb.size());
  for (size_t i = 0; i < error.size(); ++i) error[i] = image.rgb[i] - reference.rgb[i];
  if (previousError_.size() == error.size()) {
    double sum = 0;
    for (size_t i = 0; i < error.size(); ++i)
      sum += double(error[i] - previousError_[i]) * (error[i] - previousError_[i]);
    flickerSum_ += std::sqrt(sum / double(std::max<size_t>(error.size(), 1)));
    ++flickerPairs_;
  }
  previousError_ = std::move(error);
}

std::optional<double> SequenceError::lagPsnrDb() const {
  if (!lagFrames_) return std::nullopt;
  return lagSum_ / lagFrames_;
}

}  // namespace app
