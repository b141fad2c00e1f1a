# antipode_add_plugin(NAME SOURCES src... [LIBRARIES lib...])
# Builds one plugin shared library into the build tree's plugin directory (where the plugin
# host finds it) and installs it into the install prefix's plugin directory.
function(antipode_add_plugin name)
  cmake_parse_arguments(ARG "" "" "SOURCES;LIBRARIES" ${ARGN})
  add_library(${name} MODULE ${ARG_SOURCES})
  target_link_libraries(${name} PRIVATE antipode::framework ${ARG_LIBRARIES})
  set_target_properties(${name} PROPERTIES
    PREFIX "libantipode_"
    LIBRARY_OUTPUT_DIRECTORY "${ANTIPODE_PLUGIN_BUILD_DIR}"
    CXX_VISIBILITY_PRESET hidden
    VISIBILITY_INLINES_HIDDEN ON)
  install(TARGETS ${name} LIBRARY DESTINATION "${ANTIPODE_PLUGIN_INSTALL_DIR}")
endfunction()
