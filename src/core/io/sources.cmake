# Crash-safe file output, whole-file reads, FoamFile headers, the case lock.
target_sources(isphCore PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/AtomicFile.cpp
  ${CMAKE_CURRENT_LIST_DIR}/CaseLock.cpp
  ${CMAKE_CURRENT_LIST_DIR}/FoamFileHeader.cpp
  ${CMAKE_CURRENT_LIST_DIR}/ReadFile.cpp
  ${CMAKE_CURRENT_LIST_DIR}/StagingNames.cpp
  ${CMAKE_CURRENT_LIST_DIR}/StagingRecovery.cpp
)
