// SPDX-License-Identifier: Apache-2.0
// Beam observation streams (`beams filter --stream`): WordReader on a stream that arrives in
// pieces of 1 to 8 bytes, as a sensor feed does. It must deliver what parse_word finds in
// the whole text, observation by observation, and stop with the same error at the same place.
#include "beam_alphabets.hpp"
#include "fuzz.hpp"

#include <istream>
#include <streambuf>

namespace {

// Hands the text out in pieces whose sizes come from the text itself.
class PieceBuf : public std::streambuf {
 public:
  explicit PieceBuf(const std::string& s) : s_(s) {}

 protected:
  int_type underflow() override {
    if (pos_ >= s_.size()) return traits_type::eof();
    const std::size_t n = std::min<std::size_t>(1 + static_cast<unsigned char>(s_[pos_]) % 8, s_.size() - pos_);
    char* b = const_cast<char*>(s_.data()) + pos_;
    setg(b, b, b + n);
    pos_ += n;
    return traits_type::to_int_type(*b);
  }

 private:
  const std::string& s_;
  std::size_t pos_ = 0;
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace preimage;
  static const auto alphabets = fuzz::beam_alphabets();
  const std::string text = fuzz::text_of(data, size);
  for (const beams::Alphabet& A : alphabets) {
    std::vector<beams::Symbol> whole;
    std::string whole_error;
    try {
      whole = A.parse_word(text);
    } catch (const InputError& e) {
      whole_error = e.what();
    }
    PieceBuf buf(text);
    std::istream in(&buf);
    beams::WordReader r(A, in);
    std::vector<beams::Symbol> streamed;
    std::string stream_error;
    try {
      beams::Symbol y;
      std::string token;
      while (r.next(y, &token)) {
        streamed.push_back(y);
        if (token != A.format(y)) fuzz::fail("the reported token is not the observation's name");
      }
    } catch (const InputError& e) {
      stream_error = e.what();
    }
    if (stream_error != whole_error) fuzz::fail("the stream stops with another error than the whole word: '" + stream_error + "' vs '" + whole_error + "'");
    if (r.observations() != streamed.size()) fuzz::fail("observations() is not the number delivered");
    // A failing word's observations before the bad token are delivered by the stream; the
    // whole word delivers none, so compare only complete words.
    if (whole_error.empty() && streamed != whole) fuzz::fail("the stream delivers other observations than the whole word");
  }
  return 0;
}
