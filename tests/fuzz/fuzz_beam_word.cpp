// SPDX-License-Identifier: Apache-2.0
// Beam observation words (`beams filter|homotopy|winding --word`): Alphabet::parse_word
// under both alphabets; a word that parses must parse again, to the same observations,
// from its own formatted text.
#include "beam_alphabets.hpp"
#include "fuzz.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace preimage;
  static const auto alphabets = fuzz::beam_alphabets();
  const std::string text = fuzz::text_of(data, size);
  for (const beams::Alphabet& A : alphabets) {
    fuzz::expect_only_input_errors([&] {
      const std::vector<beams::Symbol> word = A.parse_word(text);
      for (beams::Symbol y : word)
        if (y >= A.num_symbols()) fuzz::fail("a symbol outside the alphabet");
      std::vector<beams::Symbol> again;
      try {
        again = A.parse_word(A.format(word));
      } catch (const InputError& e) {
        fuzz::fail(std::string("a formatted word does not parse: ") + e.what());
      }
      if (again != word) fuzz::fail("a formatted word parses to other observations");
    });
  }
  return 0;
}
