// The plugin library's entry symbol: one factory, selector "table_top_selector".
#include "antipode/plugin/abi.hpp"
#include "table_top_selector.hpp"

namespace {

antipode::Component* create_table_top_selector(const antipode::Parameters& params) {
  return new antipode::cells::TableTopSelector(params);
}

const antipode::PluginFactory kFactories[] = {
    {"selector", "table_top_selector",
     "best-scoring hands whose body clears the table plane (a baseline, no clustering)",
     &create_table_top_selector, nullptr},
};

}  // namespace

ANTIPODE_PLUGIN("table_top_selector", "0.1.0", kFactories)
