# Robot: URDF models (urdfdom), kinematic chains and inverse kinematics (orocos-kdl); tinyxml2
# bounds a description's nesting before urdfdom's recursive TinyXML parser reads it.
# Debian's CMake packages: urdfdom, orocos_kdl and tinyxml2 (not pkg-config).
find_package(urdfdom REQUIRED)
find_package(orocos_kdl REQUIRED)
find_package(tinyxml2 REQUIRED)
list(APPEND ANTIPODE_SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/chain_evaluator.cpp
  ${CMAKE_CURRENT_LIST_DIR}/inverse_kinematics.cpp
  ${CMAKE_CURRENT_LIST_DIR}/kinematic_chain.cpp
  ${CMAKE_CURRENT_LIST_DIR}/robot_file.cpp
  ${CMAKE_CURRENT_LIST_DIR}/robot_model.cpp)
list(APPEND ANTIPODE_PRIVATE_LIBS urdfdom::urdfdom_model orocos-kdl tinyxml2::tinyxml2)
list(APPEND ANTIPODE_PRIVATE_INCLUDES ${urdfdom_INCLUDE_DIRS} ${orocos_kdl_INCLUDE_DIRS})
