list(APPEND ANTIPODE_SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/dl_error.cpp
  ${CMAKE_CURRENT_LIST_DIR}/elf_check.cpp
  ${CMAKE_CURRENT_LIST_DIR}/plugin_files.cpp
  ${CMAKE_CURRENT_LIST_DIR}/plugin_host.cpp
  ${CMAKE_CURRENT_LIST_DIR}/plugin_index.cpp
  ${CMAKE_CURRENT_LIST_DIR}/plugin_kind.cpp
  ${CMAKE_CURRENT_LIST_DIR}/register_plugin_node.cpp)
