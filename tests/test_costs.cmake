# The longest tests' cost, so that a first ctest run (a fresh clone: no Testing/ cost data yet)
# starts them first and the short ones fill the cores around them; afterwards ctest's own
# measurements take over. Seconds of wall time on a 2-core machine (docs/benchmarks.md "The test
# suite"); a test missing here merely starts in its definition order. The tests CMake defines
# itself (python_api, python_install, slurm) set their COST where they are defined.
set_tests_properties(CliReproduce.QuickReportOpensInChromiumWithEveryImageAndVideo PROPERTIES COST 90)
set_tests_properties(HardwareClosedLoop.TableOneScenariosLearnAsInProcess PROPERTIES COST 40)
set_tests_properties(CliLearn.FaultsThatComeAndGo PROPERTIES COST 17)
set_tests_properties(Golden.AnExperimentFileGivesTheSameTablesAndRuns PROPERTIES COST 17)
set_tests_properties(CliLearn.TheDefaultLearnerIsThePriorWhereTheRobotsDatasetIsElseTheAnnealing PROPERTIES COST 16)
set_tests_properties(Memory.LongWalkWithCsvStaysFlat PROPERTIES COST 15)
set_tests_properties(CliCalibrate.ASmallSearchWritesItsTablesAndResumes PROPERTIES COST 15)
set_tests_properties(CliExperiment.JobsDoNotChangeTheTableAndAKilledRunResumes PROPERTIES COST 14)
set_tests_properties(LandscapeCli.QuadrupedL2MatchesABruteForceWalk PROPERTIES COST 13)
set_tests_properties(Golden.LearnTunnelAndWalkPrintWhatTheyPrinted PROPERTIES COST 13)
set_tests_properties(CliLearn.JsonHasTheDocumentedFields PROPERTIES COST 12)
