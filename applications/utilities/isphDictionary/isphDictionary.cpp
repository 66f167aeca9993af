// isphDictionary: check, print and query OpenFOAM-syntax dictionaries (a subset of
// OpenFOAM's foamDictionary). Prints the dictionary with #include and $ expanded, or one
// entry; a syntax error is reported with its file and line and a non-zero exit.
//
//   isphDictionary system/controlDict
//   isphDictionary -entry application -value system/controlDict
//   isphDictionary -entry materials/sand/phi constant/materialProperties
//   isphDictionary -entry walls/bed/frictionAngle -set 20 system/particleMeshDict
// -set changes the value in the file itself, its comments and layout kept (DictionaryEdit.hpp);
// a missing -entry is an error with a non-zero exit, which scripts rely on.
#include <iostream>
#include <sstream>

#include "core/app/Application.hpp"
#include "core/Strings.hpp"
#include "core/dictionary/Dictionary.hpp"
#include "core/dictionary/DictionaryEdit.hpp"
#include "core/io/AtomicFile.hpp"
#include "core/io/ReadFile.hpp"

namespace {

const isph::ApplicationSpec spec{
    .name = "isphDictionary",
    .description = "Check, print and query an OpenFOAM-syntax dictionary file.",
    .options = {{"entry", "name", "the entry to print; sub-dictionaries separated by '/'"},
                {"value", "", "print the value of the entry only"},
                {"set", "value", "set the -entry to this value in the file (a top-level entry is added if missing)"},
                {"keywords", "", "list the keywords of the dictionary or of the -entry sub-dictionary"}},
    .arguments = {"file"},
    .banner = false,
    .recovery = isph::CaseRecovery::none,
};

std::vector<std::string> splitPath(const std::string& path) {
  std::vector<std::string> parts;
  std::stringstream ss(path);
  for (std::string part; std::getline(ss, part, '/');) {
    if (!part.empty()) parts.push_back(part);
  }
  return parts;
}

void run(const isph::ArgList& args) {
  if (const auto value = args.option("set")) {
    const auto path = args.option("entry");
    if (!path) isph::fatalError("option -set needs -entry <name>: the entry to set");
    const std::filesystem::path file = args.arguments()[0];
    const std::string text = isph::readWholeFile(file, isph::DictionaryLimits::maxFileBytes, "a dictionary");
    isph::writeFileAtomic(file, isph::setEntryValue(text, file.string(), splitPath(*path), *value));
    return;
  }
  const isph::Dictionary dict = isph::Dictionary::readFile(args.arguments()[0]);
  const isph::Dictionary* scope = &dict;
  const isph::Entry* entry = nullptr;
  if (const auto path = args.option("entry")) {
    const auto parts = splitPath(*path);
    if (parts.empty()) isph::fatalError("option -entry expects a keyword name");
    for (std::size_t i = 0; i < parts.size(); ++i) {
      entry = &scope->entry(parts[i]);
      if (i + 1 < parts.size()) scope = &scope->subDict(parts[i]);
    }
  }
  if (args.found("keywords")) {
    const isph::Dictionary& d = entry ? scope->subDict(entry->key()) : dict;
    for (const auto& k : d.keys()) std::cout << k << '\n';
    return;
  }
  if (!entry) {
    std::cout << dict.write();
    return;
  }
  isph::Dictionary single;
  single.add(*entry);
  std::string text = single.write();
  if (args.found("value")) {
    if (entry->isDict()) {
      text = entry->dict().write();
    } else {
      // "key   value;\n" -> "value"
      text = std::string(isph::trim(text.substr(entry->key().size())));
      if (!text.empty() && text.back() == ';') text.pop_back();
      text += '\n';
    }
  }
  std::cout << text;
}

}  // namespace

int main(int argc, char* argv[]) { return isph::runApplication(spec, argc, argv, run); }
