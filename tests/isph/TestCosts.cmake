# Read by ctest after the test executables' discovered tests (TEST_INCLUDE_FILES): the COST of
# the longest, so that ctest starts them first on a fresh clone (tests/CMakeLists.txt). Seconds
# as measured on a 2-core machine (2026-12-07).
set_tests_properties(ColumnCollapseElasticPlastic.FollowsBuiEtAl2008WithAStaticWedge PROPERTIES COST 250)
set_tests_properties(GranularAtRestElasticPlastic.HoldsTheBedTractionsBelowItsTopRows PROPERTIES COST 40)
set_tests_properties(ColumnCollapse.ToeHeightAtTheWallAndAreaFollowBuiEtAl2008 PROPERTIES COST 31)
