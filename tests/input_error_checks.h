// Checking the InputErrors the readers throw: which error a call raises, and its kind, file,
// line and message form "<file>:<line>: <reason>" (host/io/errors.h).
#pragma once
#include <catch2/catch.hpp>

#include <stdexcept>
#include <string>
#include <vector>

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

// A malformed text, and the error reading it must raise.
struct BadTextCase {
  const char* name;
  std::string text;
  InputErrorKind kind;
  int line;
  const char* reason;  // a part of the reason that must appear
};

// `read(text, name)` must throw, for every case, the InputError the case describes.
template <class Read>
void checkBadTexts(const std::vector<BadTextCase>& cases, Read read) {
  for (const BadTextCase& c : cases) {
    INFO("case " << c.name);
    const InputError e = inputErrorOf([&] { read(c.text, std::string(c.name)); }, c.name);
    checkInputError(e, c.name, c.kind, c.line, c.reason);
  }
}

}  // namespace tessera::test
