# End-to-end tests of the command line: beams. Included from tests/CMakeLists.txt,
# which defines cli_test(), EXPECT, FIX, EXAMPLES, FLOORPLANS and OUT.
set(BEAMS ${EXAMPLES}/beams)
cli_test(beams_graph 0 "G: 3 regions, 6 beams \\(6 labels\\), 0 beam crossings, 11 edges" - beams graph ${BEAMS}/fig01_six_beams.json)
cli_test(beams_graph_fig3b 0 "G: 8 regions, 5 beams \\(4 labels\\), 3 beam crossings" - beams graph ${BEAMS}/fig03b_crossing.json)
cli_test(beams_graph_dot 0 "r0 -> r1 \\[label=\"a, b, c\"\\]" - beams graph ${BEAMS}/fig01_six_beams.json --dot)
cli_test(beams_graph_json_svg 0 "\"beam_crossings\": 3" ${OUT}/beams.svg beams graph ${BEAMS}/fig03b_crossing.json --json --svg ${OUT}/beams.svg)
cli_test(beams_filter_fig1 0 "possible regions after 10 observations: r2 \\(1 of 3\\)" - beams filter ${BEAMS}/fig01_six_beams.json --word cbabdeeefe)
cli_test(beams_filter_sequences 0 "possible region sequences: 1" ${OUT}/fig1.svg
         beams filter ${BEAMS}/fig01_six_beams.json --word cbabdeeefe --sequences --sample-path --svg ${OUT}/fig1.svg)
cli_test(beams_filter_cached_json 0 "\"mode\": \"cached\"" - beams filter ${BEAMS}/fig03b_crossing.json --word "a b c" --cached --json)
cli_test(beams_filter_stream 0 "3 a: 2 possible: r0 r1" ${BEAMS}/fig01_words.txt beams filter ${BEAMS}/fig01_six_beams.json --stream ${BEAMS}/fig01_words.txt)
cli_test(beams_filter_inconsistent 0 "inconsistent at observation 2 \\(token a'\\)" - beams filter ${BEAMS}/fig03b_crossing.json --word "a' a'")
cli_test(beams_filter_unknown_label fail "token 4 'x' at offset 6: unknown beam label 'x'" - beams filter ${BEAMS}/fig01_six_beams.json --word "c b a x")
cli_test(beams_filter_undirected_prime fail "beam label 'b' is undirected" - beams filter ${BEAMS}/fig03b_crossing.json --word "b'")
cli_test(beams_filter_bad_region fail "initial region 9 does not exist" - beams filter ${BEAMS}/fig01_six_beams.json --word c --from 9)
cli_test(beams_filter_point_on_beam fail "initial point \\(4, 0.5\\) is not strictly inside a region" - beams filter ${BEAMS}/fig01_six_beams.json --word c --at 4,0.5)
cli_test(beams_filter_no_word fail "give exactly one of --word and --stream" - beams filter ${BEAMS}/fig01_six_beams.json)
cli_test(beams_two_bodies 0 "Fig. 11 filter \\(4 I-states\\): D_a. the product filter says D_a" - beams filter ${BEAMS}/fig11_ring.json --word "a b c a" --bodies 2 --together)
# Several bodies on a stream: each observation is filtered as it arrives, so the lines
# before a bad token are printed before the one-line error.
cli_test(beams_two_bodies_stream_bad_tail fail "4 a: 1 possible assignments" -
         beams filter ${BEAMS}/fig11_ring.json --stream ${FIX}/words/fig11_bad_tail.txt --bodies 2 --together)
cli_test(beams_two_bodies_json 0 "\"assignments\"" - beams filter ${BEAMS}/fig11_ring.json --word "a b" --bodies 3 --distinguishable --json)

cli_test(beams_simulate 0 "true region r[0-9]+ included.*true one included" ${OUT}/sim.svg beams simulate ${BEAMS}/fig03b_crossing.json --seed 3 --steps 25 --svg ${OUT}/sim.svg)
cli_test(beams_landmarks 0 "wrote .*: 20 beams" ${OUT}/lm.json beams landmarks ${BEAMS}/landmarks5.json --undirected --indistinguishable -o ${OUT}/lm.json)
cli_test(beams_landmarks_filter 0 "possible regions after" - beams filter ${BEAMS}/fig10_landmarks_undirected.json --word "1~2 2~3")
cli_test(beams_bad_beam fail "\\$\\.beams\\[0\\] \\('a'\\): from \\(1, 1\\) is not on the boundary \\(it is in free space\\)$" - beams graph ${FIX}/scenes/beam_off_boundary.json)
cli_test(beams_bad_shape fail "\\$\\.beams\\[0\\]\\.shape: expected \"segment\", \"ray\" or \"line\"" - beams graph ${FIX}/scenes/beam_bad_shape.json)
# Homotopy classes and winding numbers (sections 5-6).
cli_test(beams_winding_paper_example 0 "^winding numbers: \\(2, -3\\)$" -
         beams winding ${BEAMS}/fig13_perfect.json --word "b1 b2 b1' b2 b2 b1 b2' b2' b1 b2' b2' b2' b2'")
cli_test(beams_homotopy_commutator 0 "^  r0: o1 o2 o1' o2'   winding \\(0, 0\\)$" -
         beams homotopy ${BEAMS}/fig18_commutator.json --word "a b a' b'")
cli_test(beams_homotopy_commutator_tree 0 "^homotopy class: a b a' b'$" -
         beams homotopy ${BEAMS}/fig18_commutator.json --word "a b a' b'" --basis tree)
cli_test(beams_homotopy_tree_json 0 "\"word\": \"a b a' b'\"" - beams homotopy ${BEAMS}/fig18_commutator.json --word "a b a' b'" --basis tree --json)
cli_test(beams_homotopy_tree_drops 0 "c: .*joins o3 .*. winds \\+1 around o3 o4$" ${OUT}/tree.svg
         beams homotopy ${BEAMS}/fig15_tree.json --word "a c d' b e'" --basis tree --svg ${OUT}/tree.svg)
cli_test(beams_homotopy_fig1_open 0 "\"count\": 2," - beams homotopy ${BEAMS}/fig01_six_beams.json --word cbabdeeefe --open --json)
cli_test(beams_homotopy_limit 0 "listed 1 of 2. raise --limit" ${OUT}/fig1-basis.svg
         beams homotopy ${BEAMS}/fig01_six_beams.json --word cbabdeeefed --limit 1 --svg ${OUT}/fig1-basis.svg)
cli_test(beams_homotopy_fixed_ends 0 "^region sequences: 1. homotopy classes: 2$" -
         beams homotopy ${BEAMS}/fig01_six_beams.json --word cbabdeeefe --start 6,5 --end 10,4)
cli_test(beams_homotopy_user_basis 0 "^  r0 -> r5: s'   winding \\(-1\\)$" -
         beams homotopy ${BEAMS}/fig17_user_basis.json --word "a b c" --open)
cli_test(beams_homotopy_not_a_loop 0 "not a loop \\(try --open" - beams homotopy ${BEAMS}/fig03b_crossing.json --word "a b")
cli_test(beams_winding_general 0 "^  r0 -> r5: \\(-1\\)$" -
         beams winding ${BEAMS}/fig03b_crossing.json --word "a b c" --open)
cli_test(beams_winding_landmarks_tree 0 "^winding numbers: \\(1, 0, 0, 0, -1\\)$" -
         beams winding ${BEAMS}/fig06b_landmarks_north.json --word "1 5 5' 5'")
cli_test(beams_homotopy_not_sufficient fail "region r0 around \\(6, 4\\) is not simply connected, it surrounds o2 \\(\\$\\.environment\\.obstacles\\[1\\]\\)" -
         beams homotopy ${FIX}/scenes/beams_not_sufficient.json --word a)
cli_test(beams_homotopy_tree_needs_ddd fail "basis tree: o1 .* is not joined to the outer boundary" -
         beams homotopy ${BEAMS}/fig01_six_beams.json --word a --basis tree)
cli_test(beams_homotopy_imaginary_crossing fail "\\$\\.imaginary_beams\\[0\\] \\('p'\\): imaginary beams must be disjoint" -
         beams homotopy ${FIX}/scenes/imaginary_beams_crossing.json --word a)
cli_test(beams_homotopy_start_on_beam fail "start point \\(4, 0\\.5\\) is not strictly inside a region" -
         beams homotopy ${BEAMS}/fig01_six_beams.json --word c --start 4,0.5)
cli_test(beams_homotopy_bad_basis fail "--basis: expected imaginary or tree, got 'x'" - beams homotopy ${BEAMS}/fig01_six_beams.json --word c --basis x)

# ---------------------------------------------------------------- landmarks
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
