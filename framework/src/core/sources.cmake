list(APPEND ANTIPODE_SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/atomic_file.cpp
  ${CMAKE_CURRENT_LIST_DIR}/input_file.cpp
  ${CMAKE_CURRENT_LIST_DIR}/yaml_limits.cpp
  ${CMAKE_CURRENT_LIST_DIR}/binary_file.cpp
  ${CMAKE_CURRENT_LIST_DIR}/cell.cpp
  ${CMAKE_CURRENT_LIST_DIR}/clearing_run.cpp
  ${CMAKE_CURRENT_LIST_DIR}/cloud.cpp
  ${CMAKE_CURRENT_LIST_DIR}/error.cpp
  ${CMAKE_CURRENT_LIST_DIR}/hand_geometry.cpp
  ${CMAKE_CURRENT_LIST_DIR}/library_dir.cpp
  ${CMAKE_CURRENT_LIST_DIR}/names.cpp
  ${CMAKE_CURRENT_LIST_DIR}/parameters.cpp
  ${CMAKE_CURRENT_LIST_DIR}/random.cpp
  ${CMAKE_CURRENT_LIST_DIR}/rejection_counts.cpp
  ${CMAKE_CURRENT_LIST_DIR}/shipped_data.cpp
  ${CMAKE_CURRENT_LIST_DIR}/stop_token.cpp
  ${CMAKE_CURRENT_LIST_DIR}/view_selection.cpp)
