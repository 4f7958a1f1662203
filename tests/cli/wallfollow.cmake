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
# Issue 47: the docs said every polygon of 26 vertices or fewer that Strategy 2 solves,
# Strategy 6 solves too; seed 20285 (21 vertices): Strategy 2 plans, Strategy 6 does not.
cli_test(wallfollow_pursue_counterexample_20285_none 0 "Strategy 6 finds no plan \\([0-9]+ I-states explored, it is sound, not known to be complete\\)" -
         wallfollow pursue ${FIX}/wallfollow/s6_counterexample_20285.json --sensor none)
cli_test(wallfollow_pursue_counterexample_20285_gap 0 "independent check of the executed path: cleared" -
         wallfollow pursue ${FIX}/wallfollow/s6_counterexample_20285.json --sensor gap)
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
# Issue 47: fig05_rooms.json's description said six reflex vertices; it has five.
cli_test(wallfollow_fig05_five_reflex 0 "13 vertices, 5 reflex" - wallfollow cut-ordering ${WF}/fig05_rooms.json)
# Issue 47: --save into a folder it cannot create exited 0 with nothing saved, or 1 after the
# whole run with no tally; now one line naming it before any polygon is tried.
cli_test(wallfollow_completeness_save_unwritable fail "--save: .*/s6_counterexample_28.json/out: cannot create directory" -
         wallfollow completeness --polygons 1 --save ${FIX}/wallfollow/s6_counterexample_28.json/out)
# ... and a missing one is created (seed 1596, 27 vertices, is a counter-example).
add_test(NAME cli.wallfollow_completeness_save_clean COMMAND ${CMAKE_COMMAND} -E rm -rf ${OUT}/wallfollow-save)
set_tests_properties(cli.wallfollow_completeness_save_clean PROPERTIES FIXTURES_SETUP wallfollow_save)
cli_test(wallfollow_completeness_save_creates_dir 0 "1 solved by Strategy 2 and not by Strategy 6: seed 1596 \\(27 vertices\\)"
         ${OUT}/wallfollow-save/new/wallfollow_s6_counterexample_1596.json
         wallfollow completeness --seed 1596 --polygons 1 --min-vertices 27 --max-vertices 27 --save ${OUT}/wallfollow-save/new)
set_tests_properties(cli.wallfollow_completeness_save_creates_dir PROPERTIES FIXTURES_REQUIRED wallfollow_save)
# Issue 47: a 2,000-vertex polygon printed nothing for more than 120 s; --time-limit also
# bounds Strategy 2's exploration and the tally names the polygon (no timing asserted).
cli_test(wallfollow_completeness_large_polygon_time_limit 0
         "budget exceeded: seed 1 \\(2000 vertices\\), Strategy 2 over --time-limit"
         - wallfollow completeness --polygons 1 --min-vertices 2000 --max-vertices 2000 --time-limit 1)
add_test(NAME cli.wallfollow_completeness_states_budget_json COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_SOURCE_DIR}/cli/json_expect.py
         "d['budget'] == 1 and d['over_budget'] == [{'seed': 2, 'vertices': 8, 'strategy': '2', 'limit': 'states'}]" --
         $<TARGET_FILE:preimage_cli> wallfollow completeness --seed 2 --polygons 1 --max-vertices 12 --max-states 1 --json)
cli_test(wallfollow_completeness_bad_time_limit fail "--time-limit" - wallfollow completeness --time-limit -1)
