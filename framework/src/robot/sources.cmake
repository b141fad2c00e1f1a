# Robot: URDF models (urdfdom), kinematic chains and inverse kinematics (orocos-kdl).
# Debian's CMake packages: urdfdom and orocos_kdl (not pkg-config).
find_package(urdfdom REQUIRED)
find_package(orocos_kdl REQUIRED)
list(APPEND ANTIPODE_SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/inverse_kinematics.cpp
  ${CMAKE_CURRENT_LIST_DIR}/kinematic_chain.cpp
  ${CMAKE_CURRENT_LIST_DIR}/robot_model.cpp)
list(APPEND ANTIPODE_PRIVATE_LIBS urdfdom::urdfdom_model orocos-kdl)
list(APPEND ANTIPODE_PRIVATE_INCLUDES ${urdfdom_INCLUDE_DIRS} ${orocos_kdl_INCLUDE_DIRS})
