# End-to-end tests of the command line: beams. Included from tests/CMakeLists.txt,
# which defines cli_test(), EXPECT, FIX, EXAMPLES, FLOORPLANS and OUT.
set(BEAMS ${EXAMPLES}/beams)
set(TWO_PIECES ${FIX}/scenes/beams_two_pieces_one_label.json)
# An argument that is the empty string (CMake drops "" from cli_test's ARGN).
function(cli_test_empty_word name want regex)
  add_test(NAME cli.${name} COMMAND ${EXPECT} ${want} ${regex} - -- $<TARGET_FILE:preimage_cli> ${ARGN} --word "")
endfunction()

# ---------------------------------------------------------------- graph: the multigraph G, one edge per beam piece
cli_test(beams_graph 0 "G: 3 regions, 6 beams \\(6 labels\\), 0 beam crossings, 6 beam pieces, 12 edges \\(11 distinct" -
         beams graph ${BEAMS}/fig01_six_beams.json)
cli_test(beams_graph_fig3b 0 "G: 8 regions, 5 beams \\(4 labels\\), 3 beam crossings, 11 beam pieces, 22 edges \\(20 distinct" -
         beams graph ${BEAMS}/fig03b_crossing.json)
cli_test(beams_graph_fig3b_json 0 "\"edges\":22," - beams graph ${BEAMS}/fig03b_crossing.json --json)
cli_test(beams_graph_fig3b_json_merged 0 "\"merged_edges\":20," - beams graph ${BEAMS}/fig03b_crossing.json --json --merged)
# The undirected self-loop f: two crossings of one piece, told apart by their side.
cli_test(beams_graph_self_loop_both_ways 0 "-f-> r1 \\(beam 5 piece 0, right to left\\) -f-> r1 \\(beam 5 piece 0, left to right\\)" -
         beams graph ${BEAMS}/fig01_six_beams.json)
cli_test(beams_graph_dot 0 "r1 -> r0 \\[label=\"b \\(beam 1 piece 0, right to left\\)\"\\]" - beams graph ${BEAMS}/fig01_six_beams.json --dot)
cli_test(beams_graph_dot_merged 0 "r0 -> r1 \\[label=\"a, b, c\"\\]" - beams graph ${BEAMS}/fig01_six_beams.json --dot --merged)
cli_test(beams_graph_json_svg 0 "\"beam_crossings\":3" ${OUT}/beams.svg beams graph ${BEAMS}/fig03b_crossing.json --json --svg ${OUT}/beams.svg)
# Issue 32: two pieces labelled c joining the same two regions are 4 edges, not 2.
cli_test(beams_graph_two_pieces_one_label 0 "2 beam pieces, 4 edges \\(2 distinct" - beams graph ${TWO_PIECES})
cli_test(beams_graph_two_pieces_both_named 0 "^  r0 at \\(2\\.5, 5\\): -c-> r1 \\(beam 0 piece 0, left to right\\) -c-> r1 \\(beam 1 piece 0, right to left\\)$" -
         beams graph ${TWO_PIECES})
cli_test(beams_graph_two_pieces_json 0 "\"edges\":4," - beams graph ${TWO_PIECES} --json)
cli_test(beams_graph_two_pieces_dot 0 "r0 -> r1 \\[label=\"c \\(beam 1 piece 0, right to left\\)\"\\]" - beams graph ${TWO_PIECES} --dot)
cli_test(beams_graph_two_pieces_merged 0 "^  r0 at \\(2\\.5, 5\\): -c-> r1$" - beams graph ${TWO_PIECES} --merged)

# ---------------------------------------------------------------- filter, one body
cli_test(beams_filter_fig1 0 "possible regions after 10 observations: r2 \\(1 of 3\\)" - beams filter ${BEAMS}/fig01_six_beams.json --word cbabdeeefe)
cli_test(beams_filter_sequences 0 "possible region sequences: 1" ${OUT}/fig1.svg
         beams filter ${BEAMS}/fig01_six_beams.json --word cbabdeeefe --sequences --sample-path --svg ${OUT}/fig1.svg)
cli_test(beams_filter_cached_json 0 "\"mode\":\"cached\"" - beams filter ${BEAMS}/fig03b_crossing.json --word "a b c" --cached --json)
cli_test(beams_filter_stream 0 "3 a: 2 possible: r0 r1" ${BEAMS}/fig01_words.txt beams filter ${BEAMS}/fig01_six_beams.json --stream ${BEAMS}/fig01_words.txt)
# --stream --json is JSON Lines: one record per observation as it arrives, then the summary.
cli_test(beams_filter_stream_json_lines 0 "^\\{\"observation\":1,\"regions\":\\[0,1\\],\"token\":\"c\"\\}$" -
         beams filter ${BEAMS}/fig01_six_beams.json --stream ${BEAMS}/fig01_words.txt --json)
cli_test(beams_filter_stream_json_lines_summary 0 "^\\{\"consistent\":true,\"mode\":\"plain\",\"observations\":5,\"regions\":\\[2\\],\"word\":\"c b a b d\"\\}$" -
         beams filter ${BEAMS}/fig01_six_beams.json --stream ${BEAMS}/fig01_words.txt --json)
cli_test(beams_filter_inconsistent 0 "inconsistent at observation 2 \\(token a'\\)" - beams filter ${BEAMS}/fig03b_crossing.json --word "a' a'")
cli_test(beams_filter_unknown_label fail "token 4 'x' at offset 6: unknown beam label 'x'" - beams filter ${BEAMS}/fig01_six_beams.json --word "c b a x")
cli_test(beams_filter_undirected_prime fail "beam label 'b' is undirected" - beams filter ${BEAMS}/fig03b_crossing.json --word "b'")
cli_test(beams_filter_bad_region fail "initial region 9 does not exist" - beams filter ${BEAMS}/fig01_six_beams.json --word c --from 9)
# Region ids are unsigned 32-bit: "-1" and 2^32 once wrapped to ids that exist.
cli_test(beams_filter_from_negative fail "--from: expected region ids like 0,3, got '-1'" - beams filter ${BEAMS}/fig01_six_beams.json --word c --from -1)
cli_test(beams_filter_from_past_32_bits fail "--from: expected region ids like 0,3, got '0,4294967296'" - beams filter ${BEAMS}/fig01_six_beams.json --word c --from 0,4294967296)
cli_test(beams_filter_point_on_beam fail "initial point \\(4, 0.5\\) is not strictly inside a region" - beams filter ${BEAMS}/fig01_six_beams.json --word c --at 4,0.5)
# Issue 25: the empty word is an observation sequence (no observation yet).
cli_test_empty_word(beams_filter_empty_word 0 "possible regions after 0 observations: r0 r1 r2 \\(3 of 3\\)" beams filter ${BEAMS}/fig01_six_beams.json)
cli_test_empty_word(beams_filter_empty_word_sequences 0 "possible region sequences: 3" beams filter ${BEAMS}/fig01_six_beams.json --sequences)

# Every flag works or is a usage error naming it (issue 32).
cli_test(beams_filter_no_word fail "--word or --stream is required" - beams filter ${BEAMS}/fig01_six_beams.json)
cli_test(beams_filter_word_and_stream fail "--word excludes --stream" - beams filter ${BEAMS}/fig01_six_beams.json --word c --stream ${BEAMS}/fig01_words.txt)
cli_test(beams_filter_distinguishable_needs_bodies fail "--distinguishable requires --bodies" - beams filter ${BEAMS}/fig11_ring.json --word a --distinguishable)
cli_test(beams_filter_together_needs_bodies fail "--together requires --bodies" - beams filter ${BEAMS}/fig11_ring.json --word a --together)
cli_test(beams_filter_max_mb_needs_bodies fail "--max-mb requires --bodies" - beams filter ${BEAMS}/fig11_ring.json --word a --max-mb 10)
cli_test(beams_filter_sequences_not_with_bodies fail "--bodies excludes --sequences" - beams filter ${BEAMS}/fig11_ring.json --word a --bodies 2 --sequences)
cli_test(beams_filter_sample_path_not_with_bodies fail "--bodies excludes --sample-path" - beams filter ${BEAMS}/fig11_ring.json --word a --bodies 2 --sample-path)
cli_test(beams_filter_cached_not_with_bodies fail "--bodies excludes --cached" - beams filter ${BEAMS}/fig11_ring.json --word a --bodies 2 --cached)
cli_test(beams_filter_cache_mb_needs_cached fail "--cache-mb requires --cached" - beams filter ${BEAMS}/fig11_ring.json --word a --cache-mb 8)
cli_test(beams_filter_limit_needs_a_list fail "--limit: needs --sequences, --sample-path or --bodies" - beams filter ${BEAMS}/fig11_ring.json --word a --limit 3)
cli_test(beams_filter_limit_negative fail "--limit: expected an integer from 0 to 1000000, got -1" - beams filter ${BEAMS}/fig11_ring.json --word a --sequences --limit -1)
cli_test(beams_filter_cache_mb_zero fail "--cache-mb: expected an integer from 1 to 1048576, got 0" - beams filter ${BEAMS}/fig11_ring.json --word a --cached --cache-mb 0)

# ---------------------------------------------------------------- filter, several bodies (4.2)
cli_test(beams_two_bodies 0 "Fig. 11 filter \\(4 I-states\\): D_a. the product filter says D_a" - beams filter ${BEAMS}/fig11_ring.json --word "a b c a" --bodies 2 --together)
# Several bodies on a stream: each observation is filtered as it arrives, so the lines
# before a bad token are printed before the one-line error.
cli_test(beams_two_bodies_stream_bad_tail fail "4 a: 1 possible assignments" -
         beams filter ${BEAMS}/fig11_ring.json --stream ${FIX}/words/fig11_bad_tail.txt --bodies 2 --together)
cli_test(beams_two_bodies_json 0 "\"count\":26," - beams filter ${BEAMS}/fig11_ring.json --word "a b" --bodies 3 --distinguishable --json --limit 2)
cli_test(beams_two_bodies_json_limit 0 "\"listed\":2," - beams filter ${BEAMS}/fig11_ring.json --word "a b" --bodies 3 --distinguishable --json --limit 2)
cli_test(beams_two_bodies_stream_json_lines 0 "^\\{\"count\":2,\"observation\":3,\"token\":\"c\"\\}$" -
         beams filter ${BEAMS}/fig11_ring.json --stream ${FIX}/words/fig11_together.txt --bodies 2 --together --json)
cli_test(beams_two_bodies_stream_json_lines_summary 0 "^\\{\"bodies\":2,.*\"fig11_filter\":\"D_a\",.*\"multisets\":\\[\\[\\[0,1\\],\\[2,1\\]\\]\\],.*\\}$" -
         beams filter ${BEAMS}/fig11_ring.json --stream ${FIX}/words/fig11_together.txt --bodies 2 --together --json)
# Issue 32: --bodies runs write their SVG.
cli_test(beams_two_bodies_svg 0 "wrote .*bodies.svg" ${OUT}/bodies.svg beams filter ${BEAMS}/fig11_ring.json --word "a b c" --bodies 2 --svg ${OUT}/bodies.svg)
# Fig. 12: three regions, two bodies: 3^2 = 9 tuples (the caption's "2^3 = 9" is wrong), 6 multisets.
cli_test_empty_word(beams_fig12_nine_tuples 0 "2 distinguishable bodies after 0 observations: 9 possible assignments"
                    beams filter ${BEAMS}/fig11_ring.json --bodies 2 --distinguishable --limit 9)
cli_test_empty_word(beams_fig12_six_multisets 0 "2 indistinguishable bodies after 0 observations: 6 possible multisets"
                    beams filter ${BEAMS}/fig11_ring.json --bodies 2)
# Issue 26: a negative count was an internal error; a huge one is refused with the size it implies.
cli_test(beams_bodies_negative fail "--bodies: expected an integer from 1 to 1000000000, got -1" - beams filter ${BEAMS}/fig11_ring.json --word a --bodies -1)
cli_test(beams_bodies_negative_distinguishable fail "--bodies: expected an integer from 1 to 1000000000, got -1" -
         beams filter ${BEAMS}/fig11_ring.json --word a --bodies -1 --distinguishable)
cli_test(beams_bodies_million_refused fail "--bodies 1000000: the initial I-state holds 500001500001 multisets \\(1\\.7 EiB\\) of 1000000 bodies, more than --max-mb 1024 allows" -
         beams filter ${BEAMS}/fig11_ring.json --word a --bodies 1000000)
cli_test(beams_bodies_million_distinguishable_refused fail "--bodies 1000000: the initial I-state holds more than 1\\.8e19 tuples of 1000000 bodies" -
         beams filter ${BEAMS}/fig11_ring.json --word a --bodies 1000000 --distinguishable)
cli_test(beams_bodies_million_together_runs 0 "^  \\{r0: 999997, r1: 2, r2: 1\\}$" -
         beams filter ${BEAMS}/fig11_ring.json --word "a b c a" --bodies 1000000 --together)
cli_test(beams_bodies_step_refused fail "observation 1 \\(token a\\): the next I-state of 1000000 bodies may hold up to 3000000 tuples" -
         beams filter ${BEAMS}/fig11_ring.json --word "a b c a" --bodies 1000000 --together --distinguishable)
cli_test(beams_bodies_max_mb_zero fail "--max-mb: expected an integer from 1 to 1048576, got 0" - beams filter ${BEAMS}/fig11_ring.json --word a --bodies 2 --max-mb 0)

# ---------------------------------------------------------------- simulate, landmarks, scene errors
cli_test(beams_simulate 0 "true region r[0-9]+ included.*true one included" ${OUT}/sim.svg beams simulate ${BEAMS}/fig03b_crossing.json --seed 3 --steps 25 --svg ${OUT}/sim.svg)
cli_test(beams_simulate_zero_steps 0 "^simulated 0 path segments \\(seed 1\\): 0 observations" - beams simulate ${BEAMS}/fig03b_crossing.json --steps 0)
# Issue 26: --steps -1 wrapped to a huge count and hung; 10^8 steps would take hours and ~100 GB.
cli_test(beams_simulate_negative_steps fail "--steps: expected an integer from 0 to 1000000, got -1" - beams simulate ${BEAMS}/fig03b_crossing.json --steps -1)
cli_test(beams_simulate_huge_steps fail "--steps: expected an integer from 0 to 1000000, got 100000000" - beams simulate ${BEAMS}/fig03b_crossing.json --steps 100000000)
cli_test(beams_simulate_negative_seed fail "--seed: expected an integer from 0 to 9223372036854775807, got -5" - beams simulate ${BEAMS}/fig03b_crossing.json --seed -5)
cli_test(beams_landmarks 0 "wrote .*: 20 beams" ${OUT}/lm.json beams landmarks ${BEAMS}/landmarks5.json --undirected --indistinguishable -o ${OUT}/lm.json)
cli_test(beams_landmarks_bad_model fail "--model: east not in \\{crossing,north\\}" - beams landmarks ${BEAMS}/landmarks5.json --model east -o ${OUT}/lm2.json)
cli_test(beams_landmarks_north_indistinguishable fail "--indistinguishable: only with --model crossing" -
         beams landmarks ${BEAMS}/landmarks5.json --model north --indistinguishable -o ${OUT}/lm3.json)
cli_test(beams_landmarks_filter 0 "possible regions after" - beams filter ${BEAMS}/fig10_landmarks_undirected.json --word "1~2 2~3")
cli_test(beams_bad_beam fail "\\$\\.beams\\[0\\] \\('a'\\): from \\(1, 1\\) is not on the boundary \\(it is in free space\\)$" - beams graph ${FIX}/scenes/beam_off_boundary.json)
cli_test(beams_bad_shape fail "\\$\\.beams\\[0\\]\\.shape: expected \"segment\", \"ray\" or \"line\"" - beams graph ${FIX}/scenes/beam_bad_shape.json)
# A label no word can name (it holds a space): rejected where it enters, naming it.
cli_test(beams_label_with_space fail "\\$\\.beams\\[1\\]\\.label: 'a b' cannot be written in an observation word" - beams graph ${FIX}/scenes/beam_label_with_space.json)

# ---------------------------------------------------------------- homotopy classes and winding numbers (sections 5-6)
cli_test(beams_winding_paper_example 0 "^winding numbers: \\(2, -3\\)$" -
         beams winding ${BEAMS}/fig13_perfect.json --word "b1 b2 b1' b2 b2 b1 b2' b2' b1 b2' b2' b2' b2'")
cli_test(beams_homotopy_commutator 0 "^  r0: o1 o2 o1' o2'   winding \\(0, 0\\)$" -
         beams homotopy ${BEAMS}/fig18_commutator.json --word "a b a' b'")
cli_test(beams_homotopy_commutator_tree 0 "^homotopy class: a b a' b'$" -
         beams homotopy ${BEAMS}/fig18_commutator.json --word "a b a' b'" --basis tree)
cli_test(beams_homotopy_tree_json 0 "\"word\":\"a b a' b'\"" - beams homotopy ${BEAMS}/fig18_commutator.json --word "a b a' b'" --basis tree --json)
cli_test(beams_homotopy_tree_drops 0 "c: .*joins o3 .*. winds \\+1 around o3 o4$" ${OUT}/tree.svg
         beams homotopy ${BEAMS}/fig15_tree.json --word "c d' a b' e'" --basis tree --svg ${OUT}/tree.svg)
cli_test(beams_homotopy_fig1_open 0 "\"count\":2," - beams homotopy ${BEAMS}/fig01_six_beams.json --word cbabdeeefe --open --json)
cli_test(beams_homotopy_limit 0 "listed 1 of 2. raise --limit" ${OUT}/fig1-basis.svg
         beams homotopy ${BEAMS}/fig01_six_beams.json --word cbabdeeefed --limit 1 --svg ${OUT}/fig1-basis.svg)
cli_test(beams_homotopy_fixed_ends 0 "^region sequences: 1. homotopy classes: 2$" -
         beams homotopy ${BEAMS}/fig01_six_beams.json --word cbabdeeefe --start 6,5 --end 10,4)
cli_test(beams_homotopy_user_basis 0 "^  r0 -> r5: s'   winding \\(-1\\)$" -
         beams homotopy ${BEAMS}/fig17_user_basis.json --word "a b c" --open)
cli_test(beams_winding_general 0 "^  r0 -> r5: \\(-1\\)$" -
         beams winding ${BEAMS}/fig03b_crossing.json --word "a b c" --open)
cli_test(beams_winding_landmarks_tree 0 "^winding numbers: \\(1, 0, 0, 0, -1\\)$" -
         beams winding ${BEAMS}/fig06b_landmarks_north.json --word "1 5 5' 5'")
# --open chooses the general method when winding's basis is left to the default.
cli_test(beams_winding_open_default_basis 0 "^  r0 -> r0: \\(1, 1\\)$" - beams winding ${BEAMS}/fig13_perfect.json --word "b1 b2" --open)
cli_test_empty_word(beams_homotopy_empty_word 0 "^region sequences: 3. homotopy classes: 3$" beams homotopy ${BEAMS}/fig01_six_beams.json)
# Issue 25: an impossible word gives no class and a non-zero exit, in text and JSON alike.
cli_test(beams_winding_impossible_word fail "^preimage: --word: no path explains the word \\(inconsistent at observation 2, token b\\)$" -
         beams winding ${BEAMS}/fig15_tree.json --word "a b a' b'")
cli_test(beams_winding_impossible_word_json fail "^preimage: --word: no path explains the word \\(inconsistent at observation 2, token b\\)$" -
         beams winding ${BEAMS}/fig15_tree.json --word "a b a' b'" --json)
cli_test(beams_homotopy_impossible_word fail "^preimage: --word: no path explains the word \\(inconsistent at observation 2, token b\\)$" -
         beams homotopy ${BEAMS}/fig15_tree.json --word "a b a' b'" --basis imaginary --json)
cli_test(beams_homotopy_not_a_loop fail "no region sequence returns to its start region, so no loop explains the word \\(try --open" -
         beams homotopy ${BEAMS}/fig03b_crossing.json --word "a b")
cli_test(beams_homotopy_not_sufficient fail "region r0 around \\(6, 4\\) is not simply connected, it surrounds o2 \\(\\$\\.environment\\.obstacles\\[1\\]\\)" -
         beams homotopy ${FIX}/scenes/beams_not_sufficient.json --word a)
cli_test(beams_homotopy_tree_needs_ddd fail "basis tree: o1 .* is not joined to the outer boundary" -
         beams homotopy ${BEAMS}/fig01_six_beams.json --word a --basis tree)
cli_test(beams_homotopy_imaginary_crossing fail "\\$\\.imaginary_beams\\[0\\] \\('p'\\): imaginary beams must be disjoint" -
         beams homotopy ${FIX}/scenes/imaginary_beams_crossing.json --word a)
cli_test(beams_homotopy_start_on_beam fail "start point \\(4, 0\\.5\\) is not strictly inside a region" -
         beams homotopy ${BEAMS}/fig01_six_beams.json --word c --start 4,0.5)
cli_test(beams_homotopy_bad_basis fail "--basis: x not in \\{imaginary,tree\\}" - beams homotopy ${BEAMS}/fig01_six_beams.json --word c --basis x)
cli_test(beams_homotopy_end_needs_start fail "--end requires --start" - beams homotopy ${BEAMS}/fig01_six_beams.json --word c --end 6,5)
cli_test(beams_homotopy_open_not_with_start fail "--start excludes --open" - beams homotopy ${BEAMS}/fig01_six_beams.json --word c --open --start 6,5)
cli_test(beams_winding_open_not_with_tree fail "--open: needs --basis imaginary" - beams winding ${BEAMS}/fig13_perfect.json --word b1 --open --basis tree)
cli_test(beams_winding_max_states_not_with_tree fail "--max-states: only with --basis imaginary" -
         beams winding ${BEAMS}/fig13_perfect.json --word b1 --basis tree --max-states 10)
cli_test(beams_winding_tree_limit_zero 0 "^\\(listed 0 of 1. raise --limit\\)$" - beams winding ${BEAMS}/fig13_perfect.json --word b1 --limit 0)
cli_test(beams_homotopy_limit_negative fail "--limit: expected an integer from 0 to 1000000, got -1" - beams homotopy ${BEAMS}/fig01_six_beams.json --word c --limit -1)
cli_test(beams_homotopy_max_states_zero fail "--max-states: expected an integer from 1 to 134217728, got 0" -
         beams homotopy ${BEAMS}/fig01_six_beams.json --word c --max-states 0)
cli_test(beams_winding_max_states_huge fail "--max-states: expected an integer from 1 to 134217728, got 4294967296" -
         beams winding ${BEAMS}/fig01_six_beams.json --word c --max-states 4294967296)

# ---------------------------------------------------------------- errata of the paper (docs/beams.md)
# (4) has one b2' more than (5): (2, -4), not the (2, -3) of (6).
cli_test(beams_erratum_eq4 0 "^winding numbers: \\(2, -4\\)$" -
         beams winding ${BEAMS}/fig13_perfect.json --word "b1 b2 b1' b2 b2 b1 b2' b2' b1 b2' b2' b2' b2' b2'")
# (7) counts d -2, not 1: on the tree of 6.2's text the winding vector is (0, 2, 5, 9), not (3, 2, 5, 9).
cli_test(beams_erratum_eq7 0 "^winding numbers: \\(0, 2, 5, 9\\)$" -
         beams winding ${FIX}/scenes/beams_eq7_tree.json --word "aabcbd'cbdbd'ab'b'a'cb'acaab'b'b'b'd'")
# Proposition 5.2 is false: one region sequence r0 r1 r0, three homotopy classes per start region.
cli_test(beams_erratum_prop52_six_classes 0 "^region sequences: 2. homotopy classes: 6$" - beams homotopy ${TWO_PIECES} --word "c c")
cli_test(beams_erratum_prop52_around_one_way 0 "^  r0: o1   winding \\(1\\)$" - beams homotopy ${TWO_PIECES} --word "c c")
cli_test(beams_erratum_prop52_around_other_way 0 "^  r0: o1'   winding \\(-1\\)$" - beams homotopy ${TWO_PIECES} --word "c c")
cli_test(beams_erratum_prop52_trivial 0 "^  r0: 1   winding \\(0\\)$" - beams homotopy ${TWO_PIECES} --word "c c")

# ---------------------------------------------------------------- landmarks
