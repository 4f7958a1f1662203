# End-to-end tests of the command line: landmarks. Included from tests/CMakeLists.txt,
# which defines cli_test(), EXPECT, FIX, EXAMPLES, FLOORPLANS and OUT.
set(LANDMARKS ${EXAMPLES}/landmarks)
cli_test(landmarks_order_type 0 "^convex hull, counter-clockwise: 1 2 5 8 6 4$" - landmarks order-type ${LANDMARKS}/eight.json)
cli_test(landmarks_order_type_json 0 "\"3,7\": \\[" - landmarks order-type ${LANDMARKS}/eight.json --json)
cli_test(landmarks_count_six 0 "^16 distinct order types among 5000 random sets of 6 landmarks \\(up to relabelling and reflection" -
         landmarks count-order-types 6 --samples 5000 --mirror)
cli_test(landmarks_collinear fail "\\$\\.landmarks\\[1\\] \\('b'\\), \\$\\.landmarks\\[3\\] \\('d'\\) and \\$\\.landmarks\\[4\\] \\('e'\\) are collinear" -
         landmarks order-type ${FIX}/scenes/landmarks_collinear.json)
cli_test(landmarks_hull_learn 0 "agrees with the coordinates: yes" - landmarks hull ${LANDMARKS}/eight.json --learn --start 4.5,2.3)
cli_test(landmarks_order_type_learn 0 "Strategy 1 for all 28 pairs\\). agrees with the coordinates: yes" - landmarks order-type ${LANDMARKS}/eight.json --learn)
cli_test(landmarks_start_on_line fail "robot start \\(2, 2\\) lies on the line through landmarks" - landmarks hull ${LANDMARKS}/eight.json --learn --start 2,2)
cli_test(landmarks_count_bad_n fail "N: expected 3 to 1000 landmarks, got 2" - landmarks count-order-types 2)
cli_test(landmarks_patrol 0 "^patrol route around 3 7, counter-clockwise: 1 2 8 4$" - landmarks patrol ${LANDMARKS}/eight.json --watch 3,7)
cli_test(landmarks_patrol_learn 0 "Strategy 6\\). agrees with the coordinates: yes" - landmarks patrol ${LANDMARKS}/eight.json --watch 3,7 --learn)
cli_test(landmarks_patrol_on_hull fail "landmark '1' is on the convex hull of all landmarks" - landmarks patrol ${LANDMARKS}/eight.json --watch 1)
cli_test(landmarks_patrol_bad_label fail "--watch: no landmark labelled 'x' \\(token 2, at character 3\\)" - landmarks patrol ${LANDMARKS}/eight.json --watch 3,x)
cli_test(landmarks_navigate_learn 0 "^robot: reached a cell reading the goal with [0-9]+ primitives" - landmarks navigate ${LANDMARKS}/eight.json --goal 1,3,2,5,8,6,4,7 --learn --svg ${OUT}/nav.svg)
cli_test(landmarks_navigate_outside 0 "^robot: not realizable in a cell meeting the hull: the hull landmarks are out of their counter-clockwise order" -
         landmarks navigate ${LANDMARKS}/eight.json --goal 1,5,3,7,8,4,6,2 --learn)
cli_test(landmarks_navigate_short_goal fail "--goal: a cyclic permutation of all 8 landmarks is needed, got 3" - landmarks navigate ${LANDMARKS}/eight.json --goal 1,3,2)
cli_test(landmarks_swap_graph 0 "^swap cell decomposition of 8 landmarks \\(56 swap rays\\): 153 cells, 16 meeting the hull. swap graph: 264 edges" -
         landmarks swap-graph ${LANDMARKS}/eight.json --svg ${OUT}/swap.svg)
cli_test(landmarks_swap_graph_learn 0 "^agrees with the coordinates: yes$" - landmarks swap-graph ${LANDMARKS}/six.json --learn)
cli_test(landmarks_swap_graph_fig09 0 "sharing their permutation with another cell \\(Theorem 13\\): [1-9]" - landmarks swap-graph ${LANDMARKS}/fig09_equal_outside.json)
cli_test(landmarks_swap_graph_json 0 "\"meets_hull\": true" - landmarks swap-graph ${LANDMARKS}/six.json --json)

cli_test(landmarks_subnormal_coordinates fail "\\$\\.landmarks\\[1\\]\\.at\\[0\\]: coordinate is subnormal" -
         landmarks swap-graph ${FIX}/scenes/subnormal_landmarks.json)
