#include "shared_constants.h"

#include "enum_names.h"

#include <cctype>

namespace retroaa {

std::string defineLine(const char* name, long long value) {
  return std::string("#define ") + name + " " + std::to_string(value) + "\n";
}

namespace {

// PREFIX_NAME for every row: "every_pixel" is DETECTOR_EVERY_PIXEL.
template <typename Enum, size_t N>
void defineEach(std::string& defines, const std::string& prefix, const Named<Enum> (&table)[N]) {
  for (const Named<Enum>& row : table) {
    std::string name = prefix + row.name;
    for (char& c : name) c = char(std::toupper(static_cast<unsigned char>(c)));
    defines += defineLine(name.c_str(), static_cast<long long>(row.value));
  }
}

}  // namespace

const std::string& sharedConstantDefines() {
  static const std::string defines = [] {
    std::string d;
    d += defineLine("UNIT_SLICE_WEIGHTS", kUnitSliceWeights);
    d += defineLine("UNIT_DEPTH_STENCIL", kUnitDepthStencil);
    d += defineLine("UNIT_SLICE_COUNTS", kUnitSliceCounts);
    d += defineLine("MAX_ATTACHMENTS", kMaxAttachments);
    d += "#define NO_SLICE " + std::to_string(kNoSlice) + "u\n";
    defineEach(d, "WEIGHTING_", kWeightings);
    defineEach(d, "DETECTOR_", kEdgeDetectors);
    defineEach(d, "DEPTH_BUFFER_", kDepthBufferEncodings);
    defineEach(d, "DEPTH_SOURCE_", kDepthSources);
    defineEach(d, "NORMAL_", kNormalEncodings);
    return d;
  }();
  return defines;
}

}  // namespace retroaa
