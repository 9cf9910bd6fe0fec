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
  for (const host::FrameView::MovingBox& box : view.movingBoxes) {
    retroaa::MovingObject object;
    std::memcpy(object.boxToWorld, glm::value_ptr(box.now), sizeof object.boxToWorld);
    std::memcpy(object.previousBoxToWorld, glm::value_ptr(box.before), sizeof object.previousBoxToWorld);
    frame.movingObjects.push_back(object);
  }
  return frame;
}

}  // namespace patch
