# The clipper's fuzz targets' decoding and checks, one file per target on one decoding
# (clip_decoding) and one set of exact references (clip_references): compiled into the fuzz
# targets (fuzz/CMakeLists.txt) and into the gcc regression replay (tests/replay/CMakeLists.txt).
set(EDGELAND_CLIP_FUZZ_DECODERS
  ${CMAKE_CURRENT_LIST_DIR}/clip_decoding.cpp
  ${CMAKE_CURRENT_LIST_DIR}/clip_references.cpp
  ${CMAKE_CURRENT_LIST_DIR}/clip_pair_decoders.cpp
  ${CMAKE_CURRENT_LIST_DIR}/clip_sequence_decoders.cpp
  ${CMAKE_CURRENT_LIST_DIR}/normalize_decoders.cpp
  ${CMAKE_CURRENT_LIST_DIR}/parse_decoders.cpp)
