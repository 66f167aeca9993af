# Particle field files: <time>/lagrangian/<cloud>/<field>.
target_sources(isphCore PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/FieldTextScanner.cpp
  ${CMAKE_CURRENT_LIST_DIR}/FieldHeader.cpp
  ${CMAKE_CURRENT_LIST_DIR}/FieldIO.cpp
  ${CMAKE_CURRENT_LIST_DIR}/FieldFiles.cpp
)
