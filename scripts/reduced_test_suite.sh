# Sourced by the runs of the C++ suite that repeat the standalone ctest on another build (under the
# sanitizers, inside OpenCV): they check that build, not the statistics again. Statistical tests
# repeat their code paths over many scenes: there they run their first three
# (TRIPOSE_TEST_SCENE_LIMIT; the full counts run in the standalone ctest). Left out entirely are
# those whose assertions are statistics that need every scene, on paths that the rest of the suite
# runs: the stereo RANSAC and refinement against the four-view limit; the narrow-baseline search's
# rate of lowest minima, and how often the estimators reach the optimum in the two narrow regimes
# (the search's starts and minima are listed by the test of several minima, which runs on narrow
# scenes through both estimators); the Monte-Carlo check of the pose covariance (the covariance's
# other tests run).
export TRIPOSE_TEST_SCENE_LIMIT=3
narrow_optimum=Regimes/Tripose_MlOptimum.estimates_reach_the_optimum_from_the_truth
export GTEST_FILTER="-Tripose_Stereo.ransac_reaches_the_four_view_limit_and_beats_the_alternatives:Regimes/Tripose_NarrowMinima.estimators_return_the_lowest_minimum/*:$narrow_optimum/0:$narrow_optimum/1:Tripose_PoseCovariance.consistent_with_monte_carlo"
unset narrow_optimum
