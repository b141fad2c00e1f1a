// The plugin library's entry symbol: one factory, cell "bullet_cell".
#include "antipode/plugin/abi.hpp"
#include "bullet_cell.hpp"

namespace {

antipode::Component* create_bullet_cell(const antipode::Parameters& params) {
  return new antipode::cells::BulletCell(params);
}

void check_bullet_cell(const antipode::Parameters& params) {
  antipode::cells::BulletCell::check_parameters(params);
}

const antipode::PluginFactory kFactories[] = {
    {"cell", "bullet_cell",
     "simulated table-top cell: Bullet physics, Embree depth views, free-floating gripper",
     &create_bullet_cell, nullptr},
};

const antipode::PluginParameterCheck kChecks[] = {{"bullet_cell", &check_bullet_cell}};

}  // namespace

ANTIPODE_PLUGIN_WITH_CHECKS("bullet_cell", "0.1.0", kFactories, kChecks)
