// One name table per enum: config text, toString, each key's allowed values and the GLSL `#define`s
// (shared_constants.cpp) read them, so an enum value's name is written once.
#pragma once

#include "retroaa/config.h"
#include "retroaa/types.h"

namespace retroaa {

template <typename Enum>
struct Named {
  Enum value;
  const char* name;
};

// Config keys' values.
inline constexpr Named<EdgeDetector> kEdgeDetectors[] = {
    {EdgeDetector::Depth, "depth"},       {EdgeDetector::Plane, "plane"},
    {EdgeDetector::Normal, "normal"},     {EdgeDetector::Material, "material"},
    {EdgeDetector::Coverage, "coverage"}, {EdgeDetector::EveryPixel, "every_pixel"}};
inline constexpr Named<ResolveWeighting> kWeightings[] = {
    {ResolveWeighting::Median, "median"}, {ResolveWeighting::Front, "front"}, {ResolveWeighting::Back, "back"},
    {ResolveWeighting::Fso, "fso"},       {ResolveWeighting::Mean, "mean"},   {ResolveWeighting::Window, "window"}};
inline constexpr Named<ResolveEvenSplit> kEvenSplits[] = {{ResolveEvenSplit::Auto, "auto"},
                                                          {ResolveEvenSplit::Nearer, "nearer"},
                                                          {ResolveEvenSplit::Neighbours, "neighbours"}};
inline constexpr Named<FxaaQuality> kFxaaQualities[] = {
    {FxaaQuality::Low, "low"}, {FxaaQuality::Medium, "medium"}, {FxaaQuality::High, "high"}};
inline constexpr Named<SmaaQuality> kSmaaQualities[] = {{SmaaQuality::Low, "low"},
                                                        {SmaaQuality::Medium, "medium"},
                                                        {SmaaQuality::High, "high"},
                                                        {SmaaQuality::Ultra, "ultra"}};
inline constexpr Named<SmaaEdgeDetection> kSmaaEdgeDetections[] = {
    {SmaaEdgeDetection::Luma, "luma"}, {SmaaEdgeDetection::Colour, "colour"}, {SmaaEdgeDetection::Depth, "depth"}};

// The layout's encodings, as shaders compare against them.
inline constexpr Named<DepthBufferEncoding> kDepthBufferEncodings[] = {
    {DepthBufferEncoding::Perspective, "perspective"},
    {DepthBufferEncoding::Logarithmic, "logarithmic"},
    {DepthBufferEncoding::ReversedPerspective, "reversed_perspective"},
    {DepthBufferEncoding::ReversedInfinite, "reversed_infinite"},
    {DepthBufferEncoding::PerspectiveClipZeroToOne, "perspective_clip_zero_to_one"}};
inline constexpr Named<DepthSource> kDepthSources[] = {{DepthSource::PositionChannel, "position_channel"},
                                                       {DepthSource::DepthBuffer, "depth_buffer"},
                                                       {DepthSource::WorldPosition, "world_position"}};
inline constexpr Named<NormalEncoding> kNormalEncodings[] = {
    {NormalEncoding::Xyz, "xyz"}, {NormalEncoding::Octahedral, "octahedral"}, {NormalEncoding::Spheremap, "spheremap"}};

}  // namespace retroaa
