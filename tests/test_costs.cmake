# The longest tests' cost, so that a first ctest run (a fresh clone: no Testing/ cost data yet)
# starts them first and the short ones fill the cores around them; afterwards ctest's own
# measurements take over. Seconds of wall time on a 2-core machine (docs/benchmarks.md "The test
# suite"); a test missing here merely starts in its definition order. The tests CMake defines
# itself (python_api, python_install) set their COST where they are defined.
set_tests_properties(CliReproduce.QuickReportOpensInChromiumWithEveryImageAndVideo PROPERTIES COST 80)
set_tests_properties(HardwareClosedLoop.TableOneScenariosLearnAsInProcess PROPERTIES COST 45)
set_tests_properties(Mpi.AnExperimentFileUnderTwoProcessesGivesTheFilesOfOneThread PROPERTIES COST 30)
set_tests_properties(LearningSim.RandomSearchNeedsTheMostTrials PROPERTIES COST 25)
set_tests_properties(CliExperiment.JobsDoNotChangeTheTableAndAKilledRunResumes PROPERTIES COST 23)
set_tests_properties(Terrain.RoughGroundIsAHeightfieldAndStepsAreBoxes PROPERTIES COST 22)
set_tests_properties(CliLearn.FaultsThatComeAndGo PROPERTIES COST 19)
set_tests_properties(CliCalibrate.ASmallSearchWritesItsTablesAndResumes PROPERTIES COST 18)
set_tests_properties(Sweep.PaperPresetsEqualTheirExampleFiles PROPERTIES COST 16)
set_tests_properties(CliLearn.RobustRunHoldsAndReportsItsEpisodes PROPERTIES COST 16)
set_tests_properties(Memory.LongWalkWithCsvStaysFlat PROPERTIES COST 15)
set_tests_properties(LandscapeCli.QuadrupedL2MatchesABruteForceWalk PROPERTIES COST 15)
set_tests_properties(Replay.LearningTimelineHoldsEveryEventOfTheRun PROPERTIES COST 14)
