// Headless OpenGL 4.5 core context through EGL, for tests, benchmarks and regression runs.
// Tries EGL_EXT_platform_device first (NVIDIA machines), then Mesa's surfaceless platform (llvmpipe).
#pragma once

#include <memory>
#include <stdexcept>
#include <string>

namespace host {

// What the context offers; printed into every report and image metadata.
struct ContextInfo {
  std::string platform;  // "device" or "surfaceless"
  std::string renderer;  // GL_RENDERER
  std::string version;   // GL_VERSION
  int maxSamples = 0;    // GL_MAX_SAMPLES
  bool stencilExport = false;  // ARB_shader_stencil_export
  std::string summary() const;
};

class ContextError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class HeadlessContext {
 public:
  // Throws ContextError naming what is missing (platform, version, extension).
  HeadlessContext();
  ~HeadlessContext();
  HeadlessContext(const HeadlessContext&) = delete;
  HeadlessContext& operator=(const HeadlessContext&) = delete;

  const ContextInfo& info() const { return info_; }
  // Number of GL errors reported through KHR_debug since creation (high-severity and errors only).
  int debugErrorCount() const;

  struct Impl;  // opaque EGL handles

 private:
  std::unique_ptr<Impl> impl_;
  ContextInfo info_;
};

}  // namespace host
