#include "frame_info.h"

#include <glm/gtc/type_ptr.hpp>

#include <cstring>

namespace patch {

retroaa::FrameInfo frameInfo(const host::FrameView& view) {
  retroaa::FrameInfo frame;
  frame.verticalFovRadians = view.verticalFovRadians;  // FSO passes its projection's fov
  frame.nearPlane = view.nearPlane;
  frame.farPlane = view.farPlane;
  std::memcpy(frame.viewMatrix, glm::value_ptr(view.view), sizeof frame.viewMatrix);
  std::memcpy(frame.projectionMatrix, glm::value_ptr(view.projection), sizeof frame.projectionMatrix);
  return frame;
}

}  // namespace patch
