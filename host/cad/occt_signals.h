// Open CASCADE's crashes as its exceptions while a CAD file is read (docs/cad.md, "What fails").
#pragma once

namespace tessera {

// While one lives, a crash (SIGSEGV, SIGBUS, SIGFPE, SIGILL) inside Open CASCADE's code becomes
// its exception (OSD_SIGSEGV, ...), which its own transfer catches per entity ("Entity was not
// translated") and readCadFile's OCC_CATCH_SIGNALS catches elsewhere: OCCT's handlers for those
// four (OSD::SetSignal) are installed on the first construction and the process's own put back
// when the last one goes, so an embedding program keeps its handlers outside the read; the
// other signals SetSignal takes (SIGINT, SIGTERM, ...) are given back at once. Process-wide, as
// signal handlers are: guards on several threads share one installation.
class OcctSignalsAsExceptions {
 public:
  OcctSignalsAsExceptions();
  ~OcctSignalsAsExceptions();
  OcctSignalsAsExceptions(const OcctSignalsAsExceptions&) = delete;
  OcctSignalsAsExceptions& operator=(const OcctSignalsAsExceptions&) = delete;
};

}  // namespace tessera
