#pragma once
// Changing one entry of a dictionary file in place (isphDictionary -set, as foamDictionary
// -set): only the value's text is replaced, so the file keeps its comments, layout and other
// entries. The result is parsed again; a value that does not parse is a FatalError and
// nothing is changed.
#include <string>
#include <string_view>
#include <vector>

namespace isph {

// `text` (the file `fileName`) with the value of the entry at `path` (its keyword and those of
// the sub-dictionaries it is in) replaced by `value`. A top-level entry that is not there is
// added at the end. FatalError when a sub-dictionary is missing, when the entry is a
// sub-dictionary, or when it comes from an #include or a $ expansion (another place to edit).
std::string setEntryValue(std::string_view text, const std::string& fileName, const std::vector<std::string>& path,
                          const std::string& value);

}  // namespace isph
