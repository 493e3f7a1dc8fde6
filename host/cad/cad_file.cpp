// Readers: STEPControl_Reader, IGESControl_Reader (both XSControl_Reader) and BRepTools::Read.
// OCC_CATCH_SIGNALS below turns a crash inside Open CASCADE into its exception (as OCCT itself
// is built): defined before its headers.
#define OCC_CONVERT_SIGNALS
#include "cad/cad_file.h"

#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <IGESControl_Reader.hxx>
#include <Interface_InterfaceModel.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_Printer.hxx>
#include <STEPControl_Reader.hxx>
#include <StepData_StepModel.hxx>
#include <Standard_ErrorHandler.hxx>
#include <Standard_Failure.hxx>
#include <TransferBRep.hxx>
#include <Transfer_TransientProcess.hxx>
#include <XSControl_TransferReader.hxx>
#include <XSControl_WorkSession.hxx>
#include <TCollection_AsciiString.hxx>
#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <system_error>
#include <utility>
#include <vector>

#include "cad/exchange_checks.h"
#include "cad/occt_signals.h"
#include "common/input_size.h"
#include "tessera/errors.h"

namespace tessera {
namespace {

std::string lowerExtension(const std::string& path) {
  auto dot = path.find_last_of('.');
  auto slash = path.find_last_of('/');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  std::string ext = path.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

const char* statusName(IFSelect_ReturnStatus status) {
  switch (status) {
    case IFSelect_RetVoid: return "nothing read (RetVoid)";
    case IFSelect_RetDone: return "done";
    case IFSelect_RetError: return "the file is not valid (RetError)";
    case IFSelect_RetFail: return "reading failed (RetFail)";
    case IFSelect_RetStop: return "reading stopped (RetStop)";
  }
  return "unknown status";
}

// Every entity the transfer turned into a face, by the face's TShape (faces that shape healing
// replaced after the transfer are not found: their labels then carry no entity).
void recordFaceEntities(XSControl_Reader& reader, CadFile& file) {
  const Handle(XSControl_TransferReader)& transfer = reader.WS()->TransferReader();
  const Handle(Interface_InterfaceModel)& model = reader.WS()->Model();
  if (transfer.IsNull() || model.IsNull()) return;
  const Handle(Transfer_TransientProcess)& process = transfer->TransientProcess();
  if (process.IsNull()) return;
  auto step = Handle(StepData_StepModel)::DownCast(model);
  for (int i = 1; i <= process->NbMapped(); ++i) {
    const Handle(Standard_Transient)& entity = process->Mapped(i);
    const TopoDS_Shape shape = TransferBRep::ShapeResult(process, entity);
    if (shape.IsNull() || shape.ShapeType() != TopAbs_FACE) continue;
    std::string type = model->TypeName(entity, Standard_False);
    // IGES names the class ("IGESSolid_Face"): drop its package; STEP names the entity type.
    if (auto underscore = type.find('_'); underscore != std::string::npos &&
        type.find_first_of("abcdefghijklmnopqrstuvwxyz") < underscore)
      type = type.substr(underscore + 1);
    file.faceEntities[shape.TShape().get()] =
        step.IsNull() ? "entity " + std::to_string(model->Number(entity)) + " " + type
                      : "#" + std::to_string(step->IdentLabel(entity)) + " " + type;
  }
}

// The first few messages of Fail gravity sent while it is a messenger's printer: the STEP
// parser's syntax errors ("**** ERR StepFile : Undefined Parsing: Line 6415: Incorrect syntax:
// unexpected end of file, expecting '('    ****").
class FailMessages : public Message_Printer {
 public:
  FailMessages() { SetTraceLevel(Message_Fail); }
  std::string first() const {
    const std::lock_guard<std::mutex> lock(mutex_);
    return fails_.empty() ? std::string() : fails_.front();
  }

 protected:
  void send(const TCollection_AsciiString& text, const Message_Gravity gravity) const override {
    if (gravity < Message_Fail) return;
    const std::lock_guard<std::mutex> lock(mutex_);
    if (fails_.size() < 8) fails_.emplace_back(text.ToCString());
  }

 private:
  mutable std::mutex mutex_;
  mutable std::vector<std::string> fails_;
};

// Open CASCADE's readers report on its default messenger, whose printer writes to standard
// output (the IGES reader's "Total number of loaded entities"): that put text before the
// report of `--json` and before a mesh on standard output. Its printers are set aside while a
// file is read and transferred, and its fails collected for the error of a file that does not
// read; what else matters reaches the caller as the status and the checks below. (The
// messenger is global: another thread's Open CASCADE messages during a read are not printed
// either.)
class OcctMessagesSetAside {
 public:
  OcctMessagesSetAside() : messenger_(Message::DefaultMessenger()), fails_(new FailMessages) {
    if (messenger_.IsNull()) return;
    kept_ = messenger_->Printers();
    messenger_->ChangePrinters().Clear();
    messenger_->AddPrinter(fails_);
  }
  ~OcctMessagesSetAside() {
    if (!messenger_.IsNull()) messenger_->ChangePrinters() = kept_;
  }
  OcctMessagesSetAside(const OcctMessagesSetAside&) = delete;
  OcctMessagesSetAside& operator=(const OcctMessagesSetAside&) = delete;

  std::string firstFail() const { return fails_->first(); }

 private:
  Handle(Message_Messenger) messenger_;
  Handle(FailMessages) fails_;
  Message_SequenceOfPrinters kept_;
};

// Both exchange readers: read, transfer every root, keep all roots as one shape (a compound
// of located instances for an assembly). An entity that does not load or does not transfer is
// an error naming it (exchange_checks.h), never a crash or a face gone without a word.
void readExchange(XSControl_Reader& reader, CadFile& file, const char* format) {
  const OcctMessagesSetAside quiet;
  IFSelect_ReturnStatus status = reader.ReadFile(file.path.c_str());
  if (status != IFSelect_RetDone) {
    // The parser's own words where it gave them (a STEP syntax error names its line).
    const auto [line, reason] = occtLineAndReason(quiet.firstFail());
    throw InputError(InputErrorKind::Syntax, file.path, line,
                     std::string("the ") + format + " reader could not read it: " +
                         (reason.empty() ? "" : reason + "; ") + statusName(status));
  }
  requireModelLoaded(reader, file.path, format);
  const int transferred = reader.TransferRoots();
  requireTransferComplete(reader, file.path, format);
  file.readerWarnings = transferWarnings(reader, file.path, format);
  if (transferred == 0)
    throw InputError(InputErrorKind::Topology, file.path, 0,
                     std::string("the ") + format + " file holds no shape that transfers");
  file.shape = reader.OneShape();
  recordFaceEntities(reader, file);
}

}  // namespace

CadFile readCadFile(const std::string& path) {
  CadFile file;
  file.path = path;
  if (!std::ifstream(path, std::ios::binary))
    throw InputError(InputErrorKind::Io, path, 0, "cannot open the file");
  // Open CASCADE reads by path, so its reading cannot be bounded as it goes: a device or a
  // FIFO (/dev/zero behind x.step) is refused, and a file's size is checked first.
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw InputError(InputErrorKind::Io, path, 0, "not a regular file (CAD files are read by path)");
  requireInputWithinLimit(std::filesystem::file_size(path, ec), path);
  const std::string ext = lowerExtension(path);
  const OcctSignalsAsExceptions signals;  // for every reader: OCCT's crashes as its exceptions
  try {
    OCC_CATCH_SIGNALS;  // a crash outside OCCT's own handlers: its exception, caught below
    if (ext == "step" || ext == "stp") {
      STEPControl_Reader reader;
      readExchange(reader, file, "STEP");
    } else if (ext == "iges" || ext == "igs") {
      IGESControl_Reader reader;
      readExchange(reader, file, "IGES");
    } else if (ext == "brep") {
      // From a stream that throws where it fails: on a damaged .brep (a count too large) OCCT's
      // reader went on reading past the end for ever, its stream failed at every number.
      std::ifstream in(path, std::ios::binary);
      in.exceptions(std::ios::badbit | std::ios::failbit);
      BRep_Builder builder;
      try {
        BRepTools::Read(file.shape, in, builder);
      } catch (const std::ios_base::failure&) {
        throw InputError(InputErrorKind::Syntax, path, 0,
                         "BRepTools::Read could not read it: the file ends or breaks where it "
                         "expected more");
      }
      if (file.shape.IsNull())
        throw InputError(InputErrorKind::Syntax, path, 0, "BRepTools::Read could not read it");
    } else {
      throw InputError(InputErrorKind::Syntax, path, 0,
                       "unknown CAD extension '." + ext + "' (.step, .stp, .iges, .igs, .brep)");
    }
  } catch (const Standard_Failure& failure) {
    throw InputError(InputErrorKind::Syntax, path, 0,
                     std::string("Open CASCADE failed reading it: ") + failure.GetMessageString());
  }
  if (file.shape.IsNull())
    throw InputError(InputErrorKind::Topology, path, 0, "the file yields no shape");
  return file;
}

const std::string& faceEntityLabel(const CadFile& file, const TopoDS_Face& face) {
  static const std::string none;
  auto found = file.faceEntities.find(face.TShape().get());
  return found == file.faceEntities.end() ? none : found->second;
}

}  // namespace tessera
