# Grasp labelling without plugins: surface normals and the near-antipodal check (parallel
# with TBB).
find_package(TBB REQUIRED)
list(APPEND ANTIPODE_SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/antipodal.cpp
  ${CMAKE_CURRENT_LIST_DIR}/normals.cpp)
list(APPEND ANTIPODE_PRIVATE_LIBS TBB::tbb)
