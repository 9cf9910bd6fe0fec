#include "shared_constants.h"

#include "retroaa/config.h"
#include "retroaa/types.h"

namespace retroaa {

std::string defineLine(const char* name, long long value) {
  return std::string("#define ") + name + " " + std::to_string(value) + "\n";
}

const std::string& sharedConstantDefines() {
  static const std::string defines = [] {
    std::string d;
    d += defineLine("UNIT_SLICE_WEIGHTS", kUnitSliceWeights);
    d += defineLine("UNIT_DEPTH_STENCIL", kUnitDepthStencil);
    d += defineLine("UNIT_SLICE_COUNTS", kUnitSliceCounts);
    d += defineLine("MAX_ATTACHMENTS", kMaxAttachments);
    d += "#define NO_SLICE " + std::to_string(kNoSlice) + "u\n";
    d += defineLine("WEIGHTING_MEDIAN", int(ResolveWeighting::Median));
    d += defineLine("WEIGHTING_FRONT", int(ResolveWeighting::Front));
    d += defineLine("WEIGHTING_BACK", int(ResolveWeighting::Back));
    d += defineLine("WEIGHTING_FSO", int(ResolveWeighting::Fso));
    d += defineLine("WEIGHTING_MEAN", int(ResolveWeighting::Mean));
    d += defineLine("WEIGHTING_WINDOW", int(ResolveWeighting::Window));
    d += defineLine("DETECTOR_DEPTH", int(EdgeDetector::Depth));
    d += defineLine("DETECTOR_PLANE", int(EdgeDetector::Plane));
    d += defineLine("DETECTOR_NORMAL", int(EdgeDetector::Normal));
    d += defineLine("DETECTOR_MATERIAL", int(EdgeDetector::Material));
    d += defineLine("DETECTOR_COVERAGE", int(EdgeDetector::Coverage));
    d += defineLine("DETECTOR_EVERY_PIXEL", int(EdgeDetector::EveryPixel));
    d += defineLine("DEPTH_BUFFER_PERSPECTIVE", int(DepthBufferEncoding::Perspective));
    d += defineLine("DEPTH_BUFFER_LOGARITHMIC", int(DepthBufferEncoding::Logarithmic));
    d += defineLine("DEPTH_BUFFER_REVERSED_PERSPECTIVE", int(DepthBufferEncoding::ReversedPerspective));
    d += defineLine("DEPTH_BUFFER_REVERSED_INFINITE", int(DepthBufferEncoding::ReversedInfinite));
    d += defineLine("DEPTH_SOURCE_POSITION_CHANNEL", int(DepthSource::PositionChannel));
    d += defineLine("DEPTH_SOURCE_DEPTH_BUFFER", int(DepthSource::DepthBuffer));
    d += defineLine("DEPTH_SOURCE_WORLD_POSITION", int(DepthSource::WorldPosition));
    d += defineLine("NORMAL_XYZ", int(NormalEncoding::Xyz));
    d += defineLine("NORMAL_OCTAHEDRAL", int(NormalEncoding::Octahedral));
    d += defineLine("NORMAL_SPHEREMAP", int(NormalEncoding::Spheremap));
    return d;
  }();
  return defines;
}

}  // namespace retroaa
