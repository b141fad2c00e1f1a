# antipode_add_plugin(NAME SOURCES src... [LIBRARIES lib...])
# Builds one plugin library, libantipode_NAME.so, against antipode::framework. Inside the
# antipode tree it goes to the build tree's plugin directory (where the plugin host finds it);
# in a third-party project (find_package(antipode)) to ${CMAKE_BINARY_DIR}/plugins - put that
# directory on ANTIPODE_PLUGIN_PATH. `cmake --install` puts it in
# <prefix>/<libdir>/antipode/plugins under the installing project's prefix: antipode's own
# plugin folder when that is antipode's prefix (then refresh the folder's index with
# `antipode plugins --write-index DIR`), else a folder to put on ANTIPODE_PLUGIN_PATH.
# The library is linked with -z defs (outside sanitizer builds): a symbol it uses that no
# library it links provides is a link error.
function(antipode_add_plugin name)
  cmake_parse_arguments(ARG "" "" "SOURCES;LIBRARIES" ${ARGN})
  add_library(${name} MODULE ${ARG_SOURCES})
  target_link_libraries(${name} PRIVATE antipode::framework ${ARG_LIBRARIES})
  if(DEFINED ANTIPODE_PLUGIN_BUILD_DIR)
    set(output_dir "${ANTIPODE_PLUGIN_BUILD_DIR}")
  else()
    set(output_dir "${CMAKE_BINARY_DIR}/plugins")
  endif()
  # Every symbol resolved at link time, so a missing one fails the author's build, not the
  # load. Not under sanitizers: their runtime lives in the executable, not in shared objects.
  get_directory_property(link_options LINK_OPTIONS)
  if(NOT "${CMAKE_CXX_FLAGS} ${CMAKE_MODULE_LINKER_FLAGS} ${link_options}" MATCHES "-fsanitize")
    target_link_options(${name} PRIVATE "LINKER:-z,defs")
  endif()
  set_target_properties(${name} PROPERTIES
    PREFIX "libantipode_"
    LIBRARY_OUTPUT_DIRECTORY "${output_dir}"
    CXX_VISIBILITY_PRESET hidden
    VISIBILITY_INLINES_HIDDEN ON)
  install(TARGETS ${name} LIBRARY DESTINATION "${ANTIPODE_PLUGIN_INSTALL_DIR}")
  set_property(GLOBAL APPEND PROPERTY ANTIPODE_PLUGIN_TARGETS ${name})
endfunction()
