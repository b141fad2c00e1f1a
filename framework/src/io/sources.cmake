# Cloud input: PCD and PLY files, read by the parsers here (LZF-compressed PCD data through
# liblzf); PNG output through libpng.
find_package(liblzf REQUIRED)
find_package(PNG REQUIRED)
list(APPEND ANTIPODE_SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/gripper_file.cpp
  ${CMAKE_CURRENT_LIST_DIR}/load_cloud.cpp
  ${CMAKE_CURRENT_LIST_DIR}/pcd_ascii.cpp
  ${CMAKE_CURRENT_LIST_DIR}/pcd_header.cpp
  ${CMAKE_CURRENT_LIST_DIR}/pcd_reader.cpp
  ${CMAKE_CURRENT_LIST_DIR}/pcd_writer.cpp
  ${CMAKE_CURRENT_LIST_DIR}/ply_reader.cpp
  ${CMAKE_CURRENT_LIST_DIR}/png_file.cpp
  ${CMAKE_CURRENT_LIST_DIR}/text_scan.cpp)
list(APPEND ANTIPODE_PRIVATE_LIBS liblzf::liblzf PNG::PNG)
