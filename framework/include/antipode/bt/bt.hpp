#pragma once
/// @file
/// Everything of the behaviour-tree engine in one include.

#include "antipode/bt/action_node.hpp"
#include "antipode/bt/blackboard.hpp"
#include "antipode/bt/control_node.hpp"
#include "antipode/bt/converters.hpp"
#include "antipode/bt/decorator_node.hpp"
#include "antipode/bt/loader.hpp"
#include "antipode/bt/node.hpp"
#include "antipode/bt/node_registry.hpp"
#include "antipode/bt/observer.hpp"
#include "antipode/bt/ports.hpp"
#include "antipode/bt/status.hpp"
#include "antipode/bt/tracers.hpp"
#include "antipode/bt/tree.hpp"
