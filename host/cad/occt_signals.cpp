#include "cad/occt_signals.h"

#include <OSD.hxx>
#include <csignal>
#include <iterator>
#include <mutex>

namespace tessera {
namespace {

std::mutex signalsLock;
int signalsGuards = 0;
// The crashes OCCT turns into exceptions while a guard lives; every other signal OSD::SetSignal
// takes (SIGINT and the rest: the CLI's cleanup of half-written outputs) is given back at once.
constexpr int kCrashSignals[] = {SIGSEGV, SIGBUS, SIGFPE, SIGILL};
constexpr int kOtherSignals[] = {SIGHUP,  SIGINT,  SIGQUIT, SIGTERM, SIGABRT, SIGTRAP, SIGSYS,
                                 SIGPIPE, SIGALRM, SIGUSR1, SIGUSR2, SIGXCPU, SIGXFSZ};
struct sigaction savedCrashActions[std::size(kCrashSignals)];

}  // namespace

OcctSignalsAsExceptions::OcctSignalsAsExceptions() {
  const std::lock_guard<std::mutex> lock(signalsLock);
  if (signalsGuards++ > 0) return;
  struct sigaction others[std::size(kOtherSignals)];
  for (size_t k = 0; k < std::size(kCrashSignals); ++k)
    sigaction(kCrashSignals[k], nullptr, &savedCrashActions[k]);
  for (size_t k = 0; k < std::size(kOtherSignals); ++k)
    sigaction(kOtherSignals[k], nullptr, &others[k]);
  // Floating-point traps off: OCCT's arithmetic may divide by zero on purpose.
  OSD::SetSignal(OSD_SignalMode_Set, Standard_False);
  for (size_t k = 0; k < std::size(kOtherSignals); ++k)
    sigaction(kOtherSignals[k], &others[k], nullptr);
}

OcctSignalsAsExceptions::~OcctSignalsAsExceptions() {
  const std::lock_guard<std::mutex> lock(signalsLock);
  if (--signalsGuards > 0) return;
  for (size_t k = 0; k < std::size(kCrashSignals); ++k)
    sigaction(kCrashSignals[k], &savedCrashActions[k], nullptr);
}

}  // namespace tessera
