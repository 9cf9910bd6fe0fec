// What both in-repo patches share: the frame's camera, as their engines hand it over, in the plugin's terms.
#pragma once

#include "engine.h"
#include "retroaa/plugin.h"

namespace patch {

retroaa::FrameInfo frameInfo(const host::FrameView& view);

}  // namespace patch
