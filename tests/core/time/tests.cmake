isph_add_test(testTime LABEL unit
  SOURCES
    ${CMAKE_CURRENT_LIST_DIR}/TimeNameTest.cpp
    ${CMAKE_CURRENT_LIST_DIR}/TimeSelectorTest.cpp
    ${CMAKE_CURRENT_LIST_DIR}/ControlDictTest.cpp
    ${CMAKE_CURRENT_LIST_DIR}/TimeTest.cpp
    ${CMAKE_CURRENT_LIST_DIR}/StopSignalTest.cpp
    ${CMAKE_CURRENT_LIST_DIR}/RunProgressTest.cpp
    ${CMAKE_CURRENT_LIST_DIR}/ProgressReporterTest.cpp
  LIBS isphCore)
