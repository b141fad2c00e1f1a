# Geometry: preprocessing, neighbourhoods (nanoflann, header-only), local frames, hand search
# (parallel with TBB).
find_package(TBB REQUIRED)
find_package(nanoflann REQUIRED)
list(APPEND ANTIPODE_SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/bin.cpp
  ${CMAKE_CURRENT_LIST_DIR}/convex_hull.cpp
  ${CMAKE_CURRENT_LIST_DIR}/crop.cpp
  ${CMAKE_CURRENT_LIST_DIR}/euclidean_clusters.cpp
  ${CMAKE_CURRENT_LIST_DIR}/grid_search.cpp
  ${CMAKE_CURRENT_LIST_DIR}/hand_body.cpp
  ${CMAKE_CURRENT_LIST_DIR}/hand_search.cpp
  ${CMAKE_CURRENT_LIST_DIR}/hand_search_parameters.cpp
  ${CMAKE_CURRENT_LIST_DIR}/local_frame.cpp
  ${CMAKE_CURRENT_LIST_DIR}/narrowest_extent.cpp
  ${CMAKE_CURRENT_LIST_DIR}/occlusion.cpp
  ${CMAKE_CURRENT_LIST_DIR}/plane_facing.cpp
  ${CMAKE_CURRENT_LIST_DIR}/plane_fit.cpp
  ${CMAKE_CURRENT_LIST_DIR}/point_index.cpp
  ${CMAKE_CURRENT_LIST_DIR}/preprocess.cpp
  ${CMAKE_CURRENT_LIST_DIR}/quadric.cpp
  ${CMAKE_CURRENT_LIST_DIR}/sample_choice.cpp
  ${CMAKE_CURRENT_LIST_DIR}/sample_hands.cpp
  ${CMAKE_CURRENT_LIST_DIR}/scene_description.cpp
  ${CMAKE_CURRENT_LIST_DIR}/scene_layout.cpp
  ${CMAKE_CURRENT_LIST_DIR}/slab_grid.cpp
  ${CMAKE_CURRENT_LIST_DIR}/support_plane.cpp
  ${CMAKE_CURRENT_LIST_DIR}/depth_scale.cpp
  ${CMAKE_CURRENT_LIST_DIR}/voxel_grid.cpp)
list(APPEND ANTIPODE_PRIVATE_LIBS TBB::tbb nanoflann::nanoflann)
