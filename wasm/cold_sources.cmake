# The core sources the wasm build compiles for size (HEXDUAL_WASM_COLD_FLAGS): see wasm/CMakeLists.txt
# for why each group is hot or cold. Included by the top-level CMakeLists.txt before hexdual_core is
# made, so that these sources are left out of it (they form hexdual_core_cold).
file(GLOB HEXDUAL_COLD_SOURCES ${CMAKE_SOURCE_DIR}/core/io/*.cpp ${CMAKE_SOURCE_DIR}/core/flips/*.cpp
  ${CMAKE_SOURCE_DIR}/core/ops/*.cpp ${CMAKE_SOURCE_DIR}/core/dual/dual_tracker.cpp ${CMAKE_SOURCE_DIR}/core/dual/tracker/*.cpp
  ${CMAKE_SOURCE_DIR}/core/layout/*.cpp ${CMAKE_SOURCE_DIR}/core/complex/canonical.cpp
  ${CMAKE_SOURCE_DIR}/core/complex/validate.cpp ${CMAKE_SOURCE_DIR}/core/analysis/*.cpp)
list(REMOVE_ITEM HEXDUAL_COLD_SOURCES ${CMAKE_SOURCE_DIR}/core/layout/tutte_embedding.cpp
  ${CMAKE_SOURCE_DIR}/core/layout/arap_relax.cpp)
foreach(cold degenerate pinned max_min step_geometry quality_stats positions_hash)
  list(APPEND HEXDUAL_COLD_SOURCES ${CMAKE_SOURCE_DIR}/core/geometry/${cold}.cpp)
endforeach()
