# End-to-end tests of the command line: landmarks. Included from tests/CMakeLists.txt,
# which defines cli_test(), EXPECT, FIX, EXAMPLES, FLOORPLANS and OUT.
set(LANDMARKS ${EXAMPLES}/landmarks)
# --json outputs: stdout must be one JSON document carrying what the text says.
find_package(Python3 COMPONENTS Interpreter REQUIRED)
function(landmarks_json_test name check)
  add_test(NAME cli.${name} COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_SOURCE_DIR}/cli/json_expect.py ${check} --
                                    $<TARGET_FILE:preimage_cli> landmarks ${ARGN})
endfunction()

cli_test(landmarks_order_type 0 "^convex hull, counter-clockwise: 1 2 5 8 6 4$" - landmarks order-type ${LANDMARKS}/eight.json)
cli_test(landmarks_order_type_json 0 "\"3,7\":\\[" - landmarks order-type ${LANDMARKS}/eight.json --json)
cli_test(landmarks_count_six 0 "^16 distinct order types among 5000 random sets of 6 landmarks \\(up to relabelling and reflection" -
         landmarks count-order-types 6 --samples 5000 --mirror)
cli_test(landmarks_collinear fail "\\$\\.landmarks\\[1\\] \\('b'\\), \\$\\.landmarks\\[3\\] \\('d'\\) and \\$\\.landmarks\\[4\\] \\('e'\\) are collinear" -
         landmarks order-type ${FIX}/scenes/landmarks_collinear.json)
cli_test(landmarks_hull_learn 0 "agrees with the coordinates: yes" - landmarks hull ${LANDMARKS}/eight.json --learn --start 4.5,2.3)
cli_test(landmarks_order_type_learn 0 "Strategy 1 for all 28 pairs\\). agrees with the coordinates: yes" - landmarks order-type ${LANDMARKS}/eight.json --learn)
cli_test(landmarks_start_on_line fail "robot start \\(2, 2\\) lies on the line through landmarks '1' and '3'" -
         landmarks hull ${LANDMARKS}/eight.json --learn --start 2,2)
cli_test(landmarks_start_on_line_names_labels fail "^preimage: robot start \\(100, 100\\) lies on the line through landmarks '1' and '5'$" -
         landmarks hull ${LANDMARKS}/six.json --learn --start 100,100)
cli_test(landmarks_start_out_of_range fail "^preimage: --start: coordinate 1e\\+13 is outside the supported range" -
         landmarks hull ${LANDMARKS}/six.json --learn --start 1e13,1)
cli_test(landmarks_patrol 0 "^patrol route around 3 7, counter-clockwise: 1 2 8 4$" - landmarks patrol ${LANDMARKS}/eight.json --watch 3,7)
cli_test(landmarks_patrol_learn 0 "Strategy 6\\). agrees with the coordinates: yes" - landmarks patrol ${LANDMARKS}/eight.json --watch 3,7 --learn)
cli_test(landmarks_patrol_on_hull fail "landmark '1' is on the convex hull of all landmarks" - landmarks patrol ${LANDMARKS}/eight.json --watch 1)
cli_test(landmarks_patrol_bad_label fail "--watch: no landmark labelled 'x' \\(token 2, at character 3\\)" - landmarks patrol ${LANDMARKS}/eight.json --watch 3,x)

# Counts: negative or out of range is a usage error naming the argument; huge work is refused up front.
cli_test(landmarks_count_bad_n fail "^preimage: N: expected an integer from 3 to 1000, got 2" - landmarks count-order-types 2)
cli_test(landmarks_count_negative_n fail "^preimage: N: expected an integer from 3 to 1000, got -3" - landmarks count-order-types -3)
cli_test(landmarks_count_negative_samples fail "^preimage: --samples: expected an integer from 1 to [0-9]+, got -1" -
         landmarks count-order-types 5 --samples -1)
cli_test(landmarks_count_huge_samples fail "^preimage: --samples: expected an integer from 1 to 5555555, got 1000000000000" -
         landmarks count-order-types 10 --samples 1000000000000)
cli_test(landmarks_count_work_bound fail "^preimage: --samples: at most 50 sets of 1000 landmarks \\(samples \\* N\\^2 <= 5e7" -
         landmarks count-order-types 1000 --samples 51)
cli_test(landmarks_count_negative_seed fail "^preimage: --seed: expected an integer from 0 to" - landmarks count-order-types 5 --seed -1)

# Strategy 7.
cli_test(landmarks_navigate_learn 0 "^robot: reached a cell reading the goal with [0-9]+ primitives" -
         landmarks navigate ${LANDMARKS}/eight.json --goal 1,3,2,5,8,6,4,7 --learn --svg ${OUT}/nav.svg)
cli_test(landmarks_navigate_doc_example 0 "^robot: reached a cell reading the goal .*reads 1 3 2 5 8 6 7 4$" -
         landmarks navigate ${LANDMARKS}/eight.json --goal 1,3,2,5,8,6,7,4 --learn)
cli_test(landmarks_navigate_outside 0 "^robot: not realizable in a cell meeting the hull: the hull landmarks are out of their counter-clockwise order" -
         landmarks navigate ${LANDMARKS}/eight.json --goal 1,5,3,7,8,4,6,2 --learn)
cli_test(landmarks_navigate_short_goal fail "--goal: a cyclic permutation of all 8 landmarks is needed, got 3" - landmarks navigate ${LANDMARKS}/eight.json --goal 1,3,2)
cli_test(landmarks_navigate_lemma10_counterexample 0 "^robot: reached a cell reading the goal .*reads 1 4 6 3 2 5$" -
         landmarks navigate ${FIX}/scenes/landmarks_lemma10_counterexample.json --goal 1,4,6,3,2,5 --learn)
# (3.9, 4.4) lies in the goal cell, outside the hull: the robot used to reject the goal even there.
cli_test(landmarks_navigate_lemma10_counterexample_from_goal_cell 0 "^robot: reached a cell reading the goal .*reads 1 4 6 3 2 5$" -
         landmarks navigate ${FIX}/scenes/landmarks_lemma10_counterexample.json --goal 1,4,6,3,2,5 --learn --start 3.9,4.4)
cli_test(landmarks_navigate_reason_names_labels 0 "^robot: not realizable in a cell meeting the hull: it has one polar line \\(5-1\\)" -
         landmarks navigate ${FIX}/scenes/landmarks_lemma10_counterexample.json --goal 1,2,3,6,4,5 --learn)

# Swap cells and Strategies 8-9.
cli_test(landmarks_swap_graph 0 "^swap cell decomposition of 8 landmarks \\(56 swap rays\\): 153 cells, 16 meeting the hull. swap graph: 264 edges" -
         landmarks swap-graph ${LANDMARKS}/eight.json --svg ${OUT}/swap.svg)
cli_test(landmarks_swap_graph_learn 0 "^agrees with the coordinates: yes$" - landmarks swap-graph ${LANDMARKS}/six.json --learn)
cli_test(landmarks_swap_graph_triangle_learn 0 "^learned everywhere \\(Strategy 9, with repel\\): 4 cells, 3 edges" -
         landmarks swap-graph ${FIX}/scenes/landmarks_triangle.json --learn)
cli_test(landmarks_swap_graph_fig09 0 "sharing their permutation with another cell \\(Theorem 13\\): 14$" - landmarks swap-graph ${LANDMARKS}/fig09_equal_outside.json)
cli_test(landmarks_swap_graph_json 0 "\"meets_hull\":true" - landmarks swap-graph ${LANDMARKS}/six.json --json)

# Extreme coordinates (issue 26). Outside the supported range: refused where the scene is read.
cli_test(landmarks_subnormal_coordinates fail "\\$\\.landmarks\\[1\\]\\.at\\[0\\]: coordinate is subnormal" -
         landmarks swap-graph ${FIX}/scenes/subnormal_landmarks.json)
# Supported but extreme: the clipping box once overflowed to infinity (SIGFPE).
cli_test(landmarks_tiny_scale_swap_graph 0 "^agrees with the coordinates: yes$" - landmarks swap-graph ${FIX}/scenes/landmarks_tiny_scale.json --learn)
cli_test(landmarks_tiny_scale_navigate 0 "^agrees with the coordinates: yes$" - landmarks navigate ${FIX}/scenes/landmarks_tiny_scale.json --goal 1,2,3,4 --learn)
cli_test(landmarks_far_crossing_swap_graph 0 "^agrees with the coordinates: yes$" ${OUT}/far_crossing.svg
         landmarks swap-graph ${FIX}/scenes/landmarks_far_crossing.json --learn --svg ${OUT}/far_crossing.svg)
cli_test(landmarks_far_crossing_navigate 0 "^agrees with the coordinates: yes$" - landmarks navigate ${FIX}/scenes/landmarks_far_crossing.json --goal a,b,d,c --learn)
cli_test(landmarks_scale_1e12_swap_graph 0 "^agrees with the coordinates: yes$" - landmarks swap-graph ${FIX}/scenes/landmarks_scale_1e12.json --learn)
cli_test(landmarks_scale_1e12_navigate 0 "^agrees with the coordinates: yes$" - landmarks navigate ${FIX}/scenes/landmarks_scale_1e12.json --goal 1,2,3,4 --learn)

# 400 landmarks (issue 26): Strategy 1 for all pairs runs in seconds; the swap cell decomposition (Theta(n^4)) is refused.
cli_test(landmarks_random_400_order_type_learn 0 "Strategy 1 for all 79800 pairs\\). agrees with the coordinates: yes" -
         landmarks order-type ${FIX}/scenes/landmarks_random_400.json --learn)
cli_test(landmarks_random_400_swap_graph_refused fail "^preimage: swap-graph: needs the swap cell decomposition from coordinates: 400 landmarks give about 1e\\+09 swap cells \\(Theta\\(n\\^4\\)\\). at most 60" -
         landmarks swap-graph ${FIX}/scenes/landmarks_random_400.json)
cli_test(landmarks_random_400_navigate_refused fail "^preimage: navigate: needs the swap cell decomposition from coordinates: 400 landmarks" -
         landmarks navigate ${FIX}/scenes/landmarks_random_400.json --goal 1 --learn)

# JSON outputs.
landmarks_json_test(landmarks_order_type_learn_json
  "d['learned']['agrees_with_coordinates'] and d['learned']['lambda'] == d['lambda'] and d['learned']['primitives'] > 0 and len(d['hull']) == 6"
  order-type ${LANDMARKS}/eight.json --learn --json)
landmarks_json_test(landmarks_order_type_json_parses "d['n'] == 8 and d['Lambda']['3,7'] is not None" order-type ${LANDMARKS}/eight.json --json)
landmarks_json_test(landmarks_patrol_learn_json "d['route'] == ['1', '2', '8', '4'] and d['agrees_with_coordinates'] and d['primitives'] > 0"
  patrol ${LANDMARKS}/eight.json --watch 3,7 --learn --json)
landmarks_json_test(landmarks_navigate_learn_json
  "d['robot']['reached'] and d['coordinates']['realizable_meeting_hull'] and d['goal'] == ['1', '4', '6', '3', '2', '5'] and d['robot']['agrees_with_coordinates']"
  navigate ${FIX}/scenes/landmarks_lemma10_counterexample.json --goal 1,4,6,3,2,5 --learn --json)
landmarks_json_test(landmarks_navigate_unrealizable_json "not d['robot']['reached'] and 'Lemma 3' in d['robot']['reason']"
  navigate ${LANDMARKS}/eight.json --goal 1,5,3,7,8,4,6,2 --learn --json)
landmarks_json_test(landmarks_swap_graph_json_parses
  "d['summary']['cells'] == len(d['cells']) == 153 and d['summary']['edges'] == len(d['edges']) == 264 and 'learned' not in d"
  swap-graph ${LANDMARKS}/eight.json --json)
landmarks_json_test(landmarks_swap_graph_learn_json
  "d['learned']['agrees_with_coordinates'] and d['learned']['everywhere']['cells'] == len(d['cells']) and d['learned']['everywhere']['edges'] == len(d['edges'])"
  swap-graph ${FIX}/scenes/landmarks_triangle.json --learn --json)
