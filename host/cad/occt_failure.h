// An Open CASCADE exception (Standard_Failure, which is no std::exception) as what it is to a
// caller: a file Open CASCADE could not handle. Left to escape, it ended the CLI in
// std::terminate (SIGABRT): BRepBndLib::Add threw Standard_ConstructionError on a .brep whose
// circle had a degenerate range.
#pragma once
#include <Standard_Failure.hxx>
#include <string>

#include "tessera/errors.h"

namespace tessera {

[[noreturn]] inline void throwAsInputError(const Standard_Failure& failure, const std::string& path,
                                           const char* doing) {
  const char* message = failure.GetMessageString();
  throw InputError(InputErrorKind::Syntax, path, 0,
                   std::string("Open CASCADE failed ") + doing + ": " +
                       failure.DynamicType()->Name() +
                       (message && *message ? std::string(": ") + message : std::string()));
}

}  // namespace tessera
