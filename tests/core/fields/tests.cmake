isph_add_test(testFieldIO LABEL unit
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/FieldIOTest.cpp
          ${CMAKE_CURRENT_LIST_DIR}/FieldIOErrorTest.cpp
          ${CMAKE_CURRENT_LIST_DIR}/FieldFilesTest.cpp
  LIBS isphCore)
