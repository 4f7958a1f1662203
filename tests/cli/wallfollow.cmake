# End-to-end tests of the command line: wallfollow. Included from tests/CMakeLists.txt,
# which defines cli_test(), EXPECT, FIX, EXAMPLES, FLOORPLANS and OUT.
set(WF ${EXAMPLES}/wallfollow)
cli_test(wallfollow_simulate 0 "LFOLLOW -> stage 7: EDGE\\+pebble, robot at edge v6-v1 at \\(0, 1\\)" -
         wallfollow simulate ${WF}/fig03_two_reflex.json --start 3,2 --actions "INIT,RFOLLOW,JUMP,DROP,RFOLLOW,LFOLLOW")
cli_test(wallfollow_simulate_inapplicable fail "action 3 \\(JUMP\\) is not applicable: JUMP: the robot is not at a reflex vertex" -
         wallfollow simulate ${WF}/fig03_two_reflex.json --start 3,2 --actions "INIT,DROP,JUMP")
cli_test(wallfollow_lying_pebble 0 "RFOLLOW -> stage 3: EDGE\\+pebble, robot at edge v6-v1 at \\(0, 2\\)" -
         wallfollow simulate ${WF}/fig03_two_reflex.json --start 0,4 --pebble 0,2 --actions "INIT,RFOLLOW,GRAB")
cli_test(wallfollow_bad_action fail "action 2 'JUMPP' at offset 5: unknown action" - wallfollow simulate ${WF}/fig03_two_reflex.json --actions "INIT,JUMPP")
cli_test(wallfollow_simulate_json 0 "\"k8_vertex_count\"" - wallfollow simulate ${WF}/fig05_rooms.json --actions "INIT,DROP" --json)
cli_test(wallfollow_count 0 "vertex count 13 \\(k8, Prop. 2\\)" - wallfollow count ${WF}/fig05_rooms.json)
cli_test(wallfollow_count_clockwise 0 "winding number -1" - wallfollow count ${WF}/fig03_two_reflex.json --clockwise)
cli_test(wallfollow_cut_ordering 0 "cut ordering \\(v1, v2, v3, l5, r2, v4, v5, v6, l2, r5\\)" - wallfollow cut-ordering ${WF}/fig03_two_reflex.json)
cli_test(wallfollow_learn 0 "equal to the true ordering up to relabelling: yes" ${OUT}/wallfollow-cut-diagram.svg
         wallfollow cut-ordering ${WF}/fig05_rooms.json --learn --svg ${OUT}/wallfollow-cut-diagram.svg)
cli_test(wallfollow_learn_json 0 "\"equals_true_up_to_relabelling\":true" - wallfollow cut-ordering ${WF}/fig05_rooms.json --learn --sort all-pairs --json)
cli_test(wallfollow_collinear fail "vertices 0, 1 and 2 are collinear" - wallfollow count ${FIX}/scenes/wallfollow_collinear.json)
cli_test(wallfollow_obstacles fail "needs a simply connected environment" - wallfollow count ${EXAMPLES}/gallery.json)
cli_test(wallfollow_start_outside fail "start \\(9, 9\\) is not in the environment" - wallfollow count ${WF}/fig03_two_reflex.json --start 9,9)
cli_test(wallfollow_bad_sort fail "--sort: expected quick or all-pairs" - wallfollow cut-ordering ${WF}/fig03_two_reflex.json --learn --sort bubble)
# Issue 26: 1e308 degrees overflowed to an infinite angle in radians (NaN heading, SIGFPE in GMP).
cli_test(wallfollow_count_huge_heading 0 "vertex count 6 \\(k8, Prop. 2\\)" - wallfollow count ${WF}/fig03_two_reflex.json --heading 1e308)
cli_test(wallfollow_simulate_huge_heading 0 "stage 2: " - wallfollow simulate ${WF}/fig03_two_reflex.json --start 3,2 --heading -1e308 --actions "INIT")

# Pursuit-evasion (section VI): every strategy end to end, the plan executed and checked.
cli_test(wallfollow_pursue_gap 0 "independent check of the executed path: cleared" ${OUT}/wallfollow-pursue.svg
         wallfollow pursue ${WF}/fig05_rooms.json --sensor gap --svg ${OUT}/wallfollow-pursue.svg)
cli_test(wallfollow_pursue_bitangent 0 "plan of 2 primitives from v8: RFOLLOW JUMP \\(12 I-states explored\\)" -
         wallfollow pursue ${WF}/fig05_rooms.json --sensor bitangent)
cli_test(wallfollow_pursue_pebble_json 0 "\"outcome\":\"plan\"" -
         wallfollow pursue ${WF}/fig05_rooms.json --sensor pebble --json)
cli_test(wallfollow_pursue_none 0 "independent check of the executed path: cleared" -
         wallfollow pursue ${WF}/fig09_three_teeth.json --sensor none)
cli_test(wallfollow_pursue_no_plan 0 "no plan exists for this robot \\(complete search, [0-9]+ I-states explored\\)" -
         wallfollow pursue ${WF}/three_arms.json --sensor bitangent)
cli_test(wallfollow_pursue_counterexample_none 0 "Strategy 6 finds no plan \\([0-9]+ I-states explored, it is sound, not known to be complete\\)" -
         wallfollow pursue ${FIX}/wallfollow/s6_counterexample_28.json --sensor none)
cli_test(wallfollow_pursue_counterexample_gap 0 "plan of [0-9]+ primitives" -
         wallfollow pursue ${FIX}/wallfollow/s6_counterexample_28.json --sensor gap --no-check)
cli_test(wallfollow_pursue_budget 0 "search stopped after [0-9]+ I-states \\(--max-states 2\\)" -
         wallfollow pursue ${WF}/fig05_rooms.json --sensor none --max-states 2)
cli_test(wallfollow_pursue_bad_sensor fail "--sensor: expected gap, bitangent, pebble or none, got 'sonar'" -
         wallfollow pursue ${WF}/fig05_rooms.json --sensor sonar)
cli_test(wallfollow_pursue_zero_states fail "--max-states" - wallfollow pursue ${WF}/fig05_rooms.json --max-states 0)
# Issue 47: the executed path in --json, exact (rational strings) and rounded, fed to the
# independent checker. The fixture's plan starts at a cut endpoint on an edge: the exact
# path clears; rounded, a later cut endpoint falls outside the polygon, and rounding the
# start alone leaves a contaminated region the plan never looks into again.
find_package(Python3 COMPONENTS Interpreter REQUIRED)
set(WF_CUT ${FIX}/wallfollow/start_at_cut_endpoint.json)
add_test(NAME cli.wallfollow_pursue_json_paths COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_SOURCE_DIR}/cli/json_expect.py
         "len(d['paths']) == 1 and len(d['paths'][0]) == d['primitives'] + 1 == len(d['paths_rounded'][0]) and all(isinstance(c, str) for p in d['paths'][0] for c in p) and '/' in d['paths'][0][0][0] and all(isinstance(c, float) for p in d['paths_rounded'][0] for c in p)"
         -- $<TARGET_FILE:preimage_cli> wallfollow pursue ${WF_CUT} --sensor none --json)
add_test(NAME cli.wallfollow_pursue_exact_path_passes_check
         COMMAND ${EXPECT} 0 "1 pursuer, 3 waypoints \\(exact\\): cleared" - -- bash -c
                 "\"$0\" wallfollow pursue \"$1\" --sensor none --json > \"$2\" && \"$0\" pursuit check \"$1\" --path \"$2\""
                 $<TARGET_FILE:preimage_cli> ${WF_CUT} ${OUT}/wallfollow-cut-endpoint-plan.json)
add_test(NAME cli.wallfollow_pursue_rounded_path_is_rejected
         COMMAND ${EXPECT} fail "path: pursuer 1 point 2 \\([0-9.]+, [0-9.]+\\) is not in free space \\(outside\\)$" - -- bash -c
                 "\"$0\" wallfollow pursue \"$1\" --sensor none --json | \"$3\" \"$4\" all > \"$2\" && \"$0\" pursuit check \"$1\" --path \"$2\""
                 $<TARGET_FILE:preimage_cli> ${WF_CUT} ${OUT}/wallfollow-cut-endpoint-rounded.json ${Python3_EXECUTABLE}
                 ${CMAKE_CURRENT_SOURCE_DIR}/cli/rounded_paths.py)
add_test(NAME cli.wallfollow_pursue_rounded_start_leaves_contamination
         COMMAND ${EXPECT} 0 "1 pursuer, 3 waypoints \\(exact\\): NOT cleared: 1 region contaminated at the end" - -- bash -c
                 "\"$0\" wallfollow pursue \"$1\" --sensor none --json | \"$3\" \"$4\" start > \"$2\" && \"$0\" pursuit check \"$1\" --path \"$2\""
                 $<TARGET_FILE:preimage_cli> ${WF_CUT} ${OUT}/wallfollow-cut-endpoint-start-rounded.json ${Python3_EXECUTABLE}
                 ${CMAKE_CURRENT_SOURCE_DIR}/cli/rounded_paths.py)
cli_test(wallfollow_pursue_holes fail "needs a simply connected environment" - wallfollow pursue ${EXAMPLES}/pursuit/pillar.json)
cli_test(wallfollow_completeness 0 "Strategy 6 plans checked: [0-9]+, not clearing: 0" -
         wallfollow completeness --polygons 6 --max-vertices 16)
cli_test(wallfollow_completeness_json 0 "\"strategy6_plans_not_clearing\":0" - wallfollow completeness --polygons 3 --max-vertices 12 --json)
cli_test(wallfollow_completeness_range fail "--min-vertices: more than --max-vertices" - wallfollow completeness --min-vertices 20 --max-vertices 10)
