# Robustness tests (project issue 8): a generated corpus of bad and degenerate inputs and
# absurd parameters, noise/outliers/non-uniform sampling on the bunny, determinism over runs
# and thread counts, and the memory guard. Every case runs in a forked child with a time
# limit, so a crash or a hang is reported with the case's name.
# Included from test/ISM_reconstruction_3/CMakeLists.txt; needs the ISM_reconstruction_3
# target and ISM_DATA_DIR (meshes extracted at configure time).
add_executable(test_robustness ${CMAKE_CURRENT_SOURCE_DIR}/test_robustness.cpp)
target_include_directories(test_robustness PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/common)
target_link_libraries(test_robustness PRIVATE ISM_reconstruction_3)

# generated files go here, one directory per test so that ctest -j can run them together
set(ISM_ROBUSTNESS_TMP ${CMAKE_CURRENT_BINARY_DIR}/robustness_tmp)

# One CTest test per section, and one per noise/outlier/sampling case, so that a failing
# case shows by name in the CTest summary.
foreach(section corpus noise_clean noise_gauss_0.25 noise_gauss_0.5 outliers_1 outliers_far nonuniform nonuniform_dense
                determinism memory)
  add_test(NAME robustness_${section}
           COMMAND test_robustness ${ISM_DATA_DIR}/meshes ${ISM_ROBUSTNESS_TMP}/${section} ${section})
  set_tests_properties(robustness_${section} PROPERTIES LABELS "robustness" TIMEOUT 1800)
endforeach()
# The memory cases limit the child's address space with setrlimit(RLIMIT_AS), which
# AddressSanitizer's shadow memory makes impossible: not run in sanitizer builds.
set_tests_properties(robustness_memory PROPERTIES LABELS "robustness;no_sanitizer")
# The package's memory guard (internal/memory_budget.h) refuses the cases that do not fit
# in the child's 2 GB before allocating: about 45 s and at most 0.7 GB resident in all.

# noise_gauss_0.5 passes since session 13 (the inside sweep of the thin-handle removal
# ordered by the tangent-plane depth on noisy points): before, 1 query of the 46k farther
# than 1 % of the diagonal was on the wrong side, 1.14 % from the truth, where the core of
# an ear's base was cut (8 wrong queries before the escape rays of session 11, 20-35 before
# the jet smoothing of noisy points). The ears are 1.9 % of the diagonal thick, about four
# times the noise; more or fewer smoothing passes or neighbours, surface refinement passes or
# a larger thin-handle depth leave 0-4 such queries per sampling, with genus 1-3 on some.
# nonuniform (36k points in all, its sparse half 5.5 times sparser than the 36k bunny, points
# about an ear's thickness apart) passes since session 16: the winding number of the points
# fills the pockets a few leaves deep that every local test confirmed there (before: genus 1
# and 6 far-wrong queries, dents at the ears and the head of the sparse half). Over 20
# samplings it meets the bar on 10 (0 before), 13 since the refinement passes on the sparse
# half's larger leaves (session 19); nonuniform_dense, the 36k bunny's density on the
# sparse half, passes (5 of 5 samplings, session 10; 2 of 2, session 16; 20 of 20, session 19). The outliers case
# passes since the tangent-plane signs, the clean and 0.25 % noise cases since the refinement
# of the leaves that miss the points.
# One sampling per case: over 20 samplings (session 19) the bar is met on 19 at 0.5 % noise, on
# 20 at 0.25 %, clean and with 1 % outliers, on 13 non-uniform (README, "Measured" and "Known
# limitations").
# Run them with: test_robustness <meshes> <tmp> <section>; ISM_ROBUSTNESS_SEED=s takes another
# sampling.
