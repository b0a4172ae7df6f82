# The suite's longest tests, run first: ctest starts tests with a higher COST first when it has
# no timings of its own yet (a clean clone, as in CI), so that the suite does not end waiting on
# one long test started last. COST is the test's time in seconds on 2 cores (release build; the
# sanitizer build's unit tests, PlantPaths and the walk cost among them, measured there). Once
# ctest has timed a run (Testing/Temporary/CTestCostData.txt) it uses its own timings instead.
# Included from the last test folder (tests/CMakeLists.txt), when every other test is defined;
# names that are not built in a configuration are ignored.
set_tests_properties(BenchSceneCli.QuickRunHasEveryModeWithFiniteNumbers PROPERTIES COST 21)
set_tests_properties(PlantPaths.NoTextureOverAlphaAlongTheWalkPath PROPERTIES COST 20)
set_tests_properties(
  PlantPaths.NoTextureOverAlphaAlongTheWallPath
  PlantPaths.ThePlantHasBothLevelsOfBeyondSides
  PROPERTIES COST 18)
set_tests_properties(tools_window_tiling_cli_test PROPERTIES COST 14)
set_tests_properties(RunCli.DemoWritesTheReportWithAllFourRuns PROPERTIES COST 13)
set_tests_properties(BenchSceneCli.ComparesAnotherSceneAndBakesOnDemandFromAnEmptyCache PROPERTIES COST 12)
set_tests_properties(
  BenchSceneCli.BadInputIsAClearError
  ClusterRun.ARankStoppedWhileRankZeroBakesEndsEveryRankAfterTheBake
  ClusterRun.ARankThatStopsAnsweringEndsEveryRankAfterTheTimeout
  RunInterrupt.CtrlCWhileBakingStopsTheBakeKeepingWhatWasFinished
  PROPERTIES COST 11)
set_tests_properties(
  AutoWalls.TheWalkCostCountsNeighboursDrawnInGeometryZonesAlongTheWalkPath
  PROPERTIES COST 10)
set_tests_properties(
  ClusterRun.ARankThatDiesEndsEveryRank
  ClusterRun.FourRanksRenderTheSameFramesAsOneProcess
  Storeys.TheClinicHasTwoStoreysAndAStair
  WallsCli.CutsAOneMeshRealModelIntoChunksAndProposesCells
  PROPERTIES COST 9)
set_tests_properties(
  BenchSceneCli.StereoRunMeasuresTheStereoErrorPerEye
  GeneratePlant.LargerTargetsMakeALongerHallWithCellsOfTheSameWeight
  RunCli.ClustersDrawTheSelectionWithinTheBudgetAndReuseTheirImpostors
  WritersCli.OutputsThatAreNotRegularFilesOrInputsAreRefused
  PROPERTIES COST 8)
set_tests_properties(
  FrustumCli.BadInputGivesAClearErrorAndNonZeroExit
  RunCli.BadFlagsAndSpecsGiveClearErrors
  RunCli.LevelsOfDetailReportTheirToleranceErrorAndBudget
  WallsCli.ProposesWallsThatPlanAccepts
  PROPERTIES COST 7)
set_tests_properties(
  AngularError.FiniteDepthZoneMaximumIsBracketedByEyes
  AutoWalls.FindsTheRoomsOfAHouseAndItsDoorwaysAsPortals
  BakeCli.BakesAGeneratedPlantAndReusesItsCache
  MeshLod.StoredErrorsAreWithinOnePercentOfDenseSampling
  RunCli.NoTexturesDrawsTheWallsCellsAndNothingOnTheWalls
  runtime_desktop_fallback
  tools_render_window_cli_test
  PROPERTIES COST 6)
set_tests_properties(
  BakeCli.EditedDepthManifestEntriesAreRebaked
  BenchSceneCli.BadCompareSceneOrOnDemandCacheIsAClearError
  BenchSceneCli.ScaleRunDrawsDepthWallsBesideFlatOnes
  CalibrateCli.RefusesBadInputWithItsMessage
  DepthWall.TexelCrossingIsTheFirstHitWithinTheLastStep
  RealScenes.EveryModelLoadsAndRendersSomethingThatIsNotUniform
  Rooms.TheClinicsStoreysHaveRoomsAndDoorways
  ViewCli.BadWordsGiveClearErrors
  PROPERTIES COST 5)
set_tests_properties(
  BakeCli.BadArgumentsAreClearErrors
  RunCli.GeometryBudgetPagesCellsAndReportsThem
  RunCli.ReplayReproducesPosesAndFramesExactly
  WallsCli.TheSmallestMinCellIsAcceptedAndASmallSplitIsNamed
  tools_view_window_cli_test
  PROPERTIES COST 4)
