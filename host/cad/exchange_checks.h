// What Open CASCADE's STEP and IGES readers say went wrong, as Tessera's errors (docs/cad.md,
// "What fails, and how it is told"). Two kinds of damage used to pass unseen:
// - an entity that does not load (a reference to an entity that is not there, or of the wrong
//   type): OCCT's transfer then dereferenced a null handle and the process died (SIGSEGV), or
//   dropped a face or an edge without a word;
// - an entity whose transfer raised (OCCT catches it and goes on): its faces are missing.
// Both are now an InputError naming the file and the entities, before any mesh is made.
#pragma once
#include <XSControl_Reader.hxx>
#include <string>
#include <utility>
#include <vector>

namespace tessera {

// An Open CASCADE message as a line and a reason: "**** ERR StepFile : Undefined Parsing: Line
// 6415: Incorrect syntax: unexpected end of file ****" → {6415, "incorrect syntax: unexpected
// end of file"}; without "Line N:", line 0 and the message without its stars and blanks.
std::pair<int, std::string> occtLineAndReason(std::string text);

// Throws InputError naming `path` and up to three entities with their messages (and how many
// more) when the loaded model has an entity that failed to load.
void requireModelLoaded(XSControl_Reader& reader, const std::string& path, const char* format);

// Throws InputError likewise when an entity's transfer failed (its shapes are then missing).
void requireTransferComplete(XSControl_Reader& reader, const std::string& path, const char* format);

// What the transfer warned of while it went on, one line per distinct message with the
// entities that gave it: "<path>: Open CASCADE's STEP transfer: null area wire detected, wire
// skipped (entity #412 FACE_BOUND; and 2 more entities)". Its shape healing says so where it
// drops or changes geometry, which a mesh then lacks without a word.
std::vector<std::string> transferWarnings(XSControl_Reader& reader, const std::string& path,
                                          const char* format);

}  // namespace tessera
