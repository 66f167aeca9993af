# Time names and selection, controlDict run controls, the run-time controller, the signals that
# stop a run, progress.
target_sources(isphCore PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/TimeName.cpp
  ${CMAKE_CURRENT_LIST_DIR}/TimeSelector.cpp
  ${CMAKE_CURRENT_LIST_DIR}/ControlDict.cpp
  ${CMAKE_CURRENT_LIST_DIR}/Time.cpp
  ${CMAKE_CURRENT_LIST_DIR}/StopSignal.cpp
  ${CMAKE_CURRENT_LIST_DIR}/RunProgress.cpp
  ${CMAKE_CURRENT_LIST_DIR}/ProgressReporter.cpp
)
