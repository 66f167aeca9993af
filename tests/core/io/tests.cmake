isph_add_test(testAtomicFile LABEL unit
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/AtomicFileTest.cpp ${CMAKE_CURRENT_LIST_DIR}/StagedDirectoryTest.cpp
          ${CMAKE_CURRENT_LIST_DIR}/StagingRecoveryTest.cpp ${CMAKE_CURRENT_LIST_DIR}/CaseLockTest.cpp
  LIBS isphCore)
isph_add_test(testFoamFileHeader LABEL unit SOURCES ${CMAKE_CURRENT_LIST_DIR}/FoamFileHeaderTest.cpp LIBS isphCore)
