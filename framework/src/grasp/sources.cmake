# Grasp labelling without plugins: surface normals, the near-antipodal check, the grasp
# hypothesis image with its HOG descriptor and the HOG + SVM classifier's model and training
# (parallel with TBB; OpenCV kept private).
find_package(TBB REQUIRED)
find_package(OpenCV REQUIRED COMPONENTS core objdetect)
set(BLA_VENDOR OpenBLAS)
find_package(BLAS REQUIRED)
find_path(OPENBLAS_INCLUDE_DIR cblas.h PATH_SUFFIXES openblas-pthread openblas REQUIRED)
list(APPEND ANTIPODE_SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/antipodal.cpp
  ${CMAKE_CURRENT_LIST_DIR}/float_product.cpp
  ${CMAKE_CURRENT_LIST_DIR}/hand_image.cpp
  ${CMAKE_CURRENT_LIST_DIR}/normals.cpp
  ${CMAKE_CURRENT_LIST_DIR}/number_codes.cpp
  ${CMAKE_CURRENT_LIST_DIR}/kernel_rows.cpp
  ${CMAKE_CURRENT_LIST_DIR}/svm_model.cpp
  ${CMAKE_CURRENT_LIST_DIR}/svm_solver.cpp
  ${CMAKE_CURRENT_LIST_DIR}/svm_training.cpp
  ${CMAKE_CURRENT_LIST_DIR}/training_examples.cpp
  ${CMAKE_CURRENT_LIST_DIR}/training_set.cpp)
list(APPEND ANTIPODE_PRIVATE_LIBS TBB::tbb opencv_core opencv_objdetect BLAS::BLAS)
list(APPEND ANTIPODE_PRIVATE_INCLUDES ${OPENBLAS_INCLUDE_DIR})
