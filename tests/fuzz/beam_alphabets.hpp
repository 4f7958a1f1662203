// SPDX-License-Identifier: Apache-2.0
// The two alphabets the beam-word harnesses parse with: one of one-character labels (the
// paper's ASCII stream, "aba'b" is four observations) and one with longer labels, where a
// token is one whole label.
#pragma once
#include <preimage/beams/alphabet.hpp>

#include <array>

namespace preimage::fuzz {

inline std::array<beams::Alphabet, 2> beam_alphabets() {
  std::array<beams::Alphabet, 2> out;
  std::uint32_t id = 0;
  for (const char* l : {"a", "b", "c", "d", "e", "f"}) out[0].add(l, true, &id);
  out[0].add("u", false, &id);  // undirected: u' is an error
  for (const char* l : {"a", "b1", "b2", "door'x"}) out[1].add(l, true, &id);
  out[1].add("gate", false, &id);
  return out;
}

}  // namespace preimage::fuzz
