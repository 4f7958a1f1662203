// SPDX-License-Identifier: Apache-2.0
#pragma once
#include <stdexcept>
#include <string>

namespace preimage {

/// Bad input: the message is one line naming the offending element
/// (JSON path, vertex indices, token and position). The CLI prints it and exits non-zero.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace preimage
