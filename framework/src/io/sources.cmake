# Cloud input: PCD and PLY files through PCL (kept private: no PCL type in a public header);
# PNG output through libpng.
find_package(PCL 1.10 REQUIRED COMPONENTS common io)
find_package(PNG REQUIRED)
list(APPEND ANTIPODE_SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/gripper_file.cpp
  ${CMAKE_CURRENT_LIST_DIR}/load_cloud.cpp
  ${CMAKE_CURRENT_LIST_DIR}/pcd_ascii.cpp
  ${CMAKE_CURRENT_LIST_DIR}/pcd_header.cpp
  ${CMAKE_CURRENT_LIST_DIR}/pcd_reader.cpp
  ${CMAKE_CURRENT_LIST_DIR}/pcl_blob.cpp
  ${CMAKE_CURRENT_LIST_DIR}/ply_reader.cpp
  ${CMAKE_CURRENT_LIST_DIR}/png_file.cpp
  ${CMAKE_CURRENT_LIST_DIR}/text_scan.cpp)
list(APPEND ANTIPODE_PRIVATE_LIBS pcl_common pcl_io PNG::PNG)
