#include "cad/exchange_checks.h"

#include <Interface_Check.hxx>
#include <Interface_CheckIterator.hxx>
#include <Interface_InterfaceModel.hxx>
#include <StepData_StepModel.hxx>
#include <TCollection_HAsciiString.hxx>
#include <XSControl_TransferReader.hxx>
#include <XSControl_WorkSession.hxx>
#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <regex>
#include <sstream>
#include <vector>

#include "tessera/errors.h"

namespace tessera {
namespace {

// "entity #1089 ADVANCED_FACE" in STEP (its own label), "entity 2 (128 0 BSplineSurface)" in
// IGES (its directory entry's number, type, form and name).
std::string entityName(const Handle(Interface_InterfaceModel) & model, int number) {
  if (model.IsNull() || number <= 0 || number > model->NbEntities()) return "the file";
  const Handle(Standard_Transient)& entity = model->Value(number);
  std::string type;
  std::istringstream words(model->TypeName(entity, Standard_False));
  for (std::string word; words >> word;) type += (type.empty() ? "" : " ") + word;
  const auto step = Handle(StepData_StepModel)::DownCast(model);
  if (!step.IsNull()) return "entity #" + std::to_string(step->IdentLabel(entity)) + " " + type;
  return "entity " + std::to_string(number) + " (" + type + ")";
}

// Throws when `checks` hold a fail: "<format> file: entity #1089 ADVANCED_FACE <verb>: <its
// messages>; ... (and N more entities)".
void requireNoFail(const Interface_CheckIterator& checks,
                   const Handle(Interface_InterfaceModel) & model, const std::string& path,
                   const char* format, const char* verb) {
  std::vector<std::string> entities, wholeFile;
  for (checks.Start(); checks.More(); checks.Next()) {
    const Handle(Interface_Check)& check = checks.Value();
    if (check.IsNull() || !check->HasFailed()) continue;
    std::string text = entityName(model, checks.Number()) + " " + verb;
    std::vector<std::string> messages;  // OCCT can say one thing twice
    for (int k = 1; k <= check->NbFails(); ++k)
      if (std::find(messages.begin(), messages.end(), check->CFail(k)) == messages.end())
        messages.push_back(check->CFail(k));
    for (size_t k = 0; k < messages.size(); ++k) text += (k ? ", " : ": ") + messages[k];
    (checks.Number() > 0 ? entities : wholeFile).push_back(std::move(text));
  }
  // A fail of the whole file (number 0: "Unresolved Reference ...") repeats what its
  // entities' fails say; it is told only where no entity has one.
  const std::vector<std::string>& told = entities.empty() ? wholeFile : entities;
  if (told.empty()) return;
  // A syntax error the parser went past names its line there ("Line 1350: ...").
  const int line = entities.empty() ? occtLineAndReason(told[0]).first : 0;
  std::string reason;
  for (size_t k = 0; k < told.size() && k < 3; ++k) reason += (k ? "; " : "") + told[k];
  if (told.size() > 3) reason += " (and " + std::to_string(told.size() - 3) + " more entities)";
  throw InputError(InputErrorKind::Syntax, path, line,
                   std::string("the ") + format + " file is damaged: " + reason);
}

}  // namespace

std::pair<int, std::string> occtLineAndReason(std::string text) {
  int line = 0;
  static const std::regex linePrefix("Line ([0-9]+): *");
  std::smatch found;
  if (std::regex_search(text, found, linePrefix)) {
    line = std::atoi(found[1].str().c_str());
    text = found.suffix().str();
  }
  const auto kept = [](char c) { return c != '*' && !std::isspace(static_cast<unsigned char>(c)); };
  const auto first = std::find_if(text.begin(), text.end(), kept);
  const auto last = std::find_if(text.rbegin(), text.rend(), kept).base();
  text = first < last ? std::string(first, last) : std::string();
  if (!text.empty()) text[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(text[0])));
  return {line, text};
}

void requireModelLoaded(XSControl_Reader& reader, const std::string& path, const char* format) {
  const Handle(XSControl_WorkSession)& session = reader.WS();
  if (session.IsNull() || session->Model().IsNull()) return;
  // The checks the reader recorded as it loaded (syntactic ones), as ModelCheckList() gives
  // them but without its semantic pass over the model: 0.2 ms against 36 ms on
  // TSM_104_01_L_DV_A.stp, whose read (418 ms) it made 9% slower.
  const Handle(Interface_InterfaceModel)& model = session->Model();
  Interface_CheckIterator loaded;
  if (model->GlobalCheck(Standard_True)->HasFailed())
    loaded.Add(model->GlobalCheck(Standard_True), 0);
  for (int k = 1; k <= model->NbEntities(); ++k) {
    const Handle(Interface_Check)& check = model->Check(k, Standard_True);
    if (!check.IsNull() && check->HasFailed()) loaded.Add(check, k);
  }
  requireNoFail(loaded, model, path, format, "does not load");
}

void requireTransferComplete(XSControl_Reader& reader, const std::string& path,
                             const char* format) {
  const Handle(XSControl_WorkSession)& session = reader.WS();
  if (session.IsNull() || session->TransferReader().IsNull()) return;
  requireNoFail(session->TransferReader()->LastCheckList(), session->Model(), path, format,
                "did not transfer");
}

std::vector<std::string> transferWarnings(XSControl_Reader& reader, const std::string& path,
                                          const char* format) {
  const Handle(XSControl_WorkSession)& session = reader.WS();
  if (session.IsNull() || session->TransferReader().IsNull()) return {};
  const Interface_CheckIterator checks = session->TransferReader()->LastCheckList();
  struct Told {
    std::string message;
    std::vector<std::string> entities;
  };
  std::vector<Told> told;  // in the order first met
  for (checks.Start(); checks.More(); checks.Next()) {
    const Handle(Interface_Check)& check = checks.Value();
    if (check.IsNull() || !check->HasWarnings()) continue;
    const std::string entity = entityName(session->Model(), checks.Number());
    for (int k = 1; k <= check->NbWarnings(); ++k) {
      const std::string message = occtLineAndReason(check->CWarning(k)).second;
      auto at = std::find_if(told.begin(), told.end(),
                             [&](const Told& t) { return t.message == message; });
      if (at == told.end()) at = told.insert(told.end(), {message, {}});
      if (at->entities.empty() || at->entities.back() != entity) at->entities.push_back(entity);
    }
  }
  std::vector<std::string> lines;
  for (const Told& t : told) {
    std::string line = path + ": Open CASCADE's " + format + " transfer: " + t.message + " (";
    // The first entity with its type, the others by their number ("entity #3471"): a STEP
    // complex entity's type lists all its parts.
    for (size_t k = 0; k < t.entities.size() && k < 3; ++k)
      line += (k ? ", " + t.entities[k].substr(0, t.entities[k].find(' ', 7)) : t.entities[k]);
    if (t.entities.size() > 3)
      line += "; and " + std::to_string(t.entities.size() - 3) + " more entities";
    lines.push_back(line + ")");
  }
  return lines;
}

}  // namespace tessera
