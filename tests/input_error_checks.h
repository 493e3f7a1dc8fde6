// Checking the InputErrors the readers throw: which error a call raises, and its kind, file,
// line and message form "<file>:<line>: <reason>" (host/io/errors.h).
#pragma once
#include <catch2/catch.hpp>

#include <stdexcept>
#include <string>

#include "io/errors.h"

namespace tessera::test {

// The InputError `call` throws; fails the test (naming `what`) if it throws none.
template <class Call>
InputError inputErrorOf(Call&& call, const std::string& what) {
  try {
    call();
  } catch (const InputError& e) {
    return e;
  }
  FAIL("no InputError for " << what);
  throw std::logic_error("unreachable");
}

// `e` is of `kind`, names `file` and `line`, reads "<file>:<line>: ..." and contains `reason`.
inline void checkInputError(const InputError& e, const std::string& file, InputErrorKind kind,
                            int line, const std::string& reason) {
  INFO("message: " << e.what());
  CHECK(inputErrorKindName(e.kind()) == std::string(inputErrorKindName(kind)));
  CHECK(e.file() == file);
  CHECK(e.line() == line);
  const std::string what = e.what();
  CHECK(what.rfind(file + ":" + std::to_string(line) + ": ", 0) == 0);
  CHECK(what.find(reason) != std::string::npos);
}

}  // namespace tessera::test
