#include "antipode/bt/status.hpp"

namespace antipode::bt {

const char* to_string(Status status) {
  switch (status) {
    case Status::kIdle:
      return "IDLE";
    case Status::kRunning:
      return "RUNNING";
    case Status::kSuccess:
      return "SUCCESS";
    case Status::kFailure:
      return "FAILURE";
  }
  return "?";
}

const char* to_string(NodeCategory category) {
  switch (category) {
    case NodeCategory::kAction:
      return "action";
    case NodeCategory::kCondition:
      return "condition";
    case NodeCategory::kControl:
      return "control";
    case NodeCategory::kDecorator:
      return "decorator";
    case NodeCategory::kSubTree:
      return "subtree";
  }
  return "?";
}

const char* to_string(PortDirection direction) {
  switch (direction) {
    case PortDirection::kInput:
      return "input";
    case PortDirection::kOutput:
      return "output";
    case PortDirection::kInOut:
      return "inout";
  }
  return "?";
}

}  // namespace antipode::bt
