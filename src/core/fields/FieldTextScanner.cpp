// Error reporting and the less frequent paths of FieldTextScanner.
#include "core/fields/FieldTextScanner.hpp"

#include <fmt/format.h>

#include <cstdlib>
#include <string>

namespace isph {

FieldTextScanner::FieldTextScanner(std::string_view text, std::size_t pos, int line,
                                   std::shared_ptr<const std::string> file)
    : text_(text), pos_(pos), lineStart_(pos), line_(line), file_(std::move(file)) {
  // Column counting needs the start of the line that `pos` is on.
  const auto nl = text_.rfind('\n', pos_ == 0 ? 0 : pos_ - 1);
  lineStart_ = (pos_ == 0 || nl == std::string_view::npos) ? 0 : nl + 1;
}

void FieldTextScanner::skipComment() {
  const SourceLocation start = here();
  if (text_[pos_ + 1] == '/') {
    while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
    return;
  }
  pos_ += 2;
  for (;;) {
    if (pos_ + 1 >= text_.size()) {
      pos_ = text_.size();
      fatalIOError(start, "the comment opened here with '/*' is not closed with '*/'");
    }
    if (text_[pos_] == '*' && text_[pos_ + 1] == '/') {
      pos_ += 2;
      return;
    }
    if (text_[pos_] == '\n') {
      ++line_;
      lineStart_ = pos_ + 1;
    }
    ++pos_;
  }
}

bool FieldTextScanner::acceptWord(std::string_view word) {
  skipSpace();
  if (text_.substr(pos_, word.size()) != word || !delimiterAt(text_.data() + pos_ + word.size()))
    return false;
  pos_ += word.size();
  return true;
}

bool FieldTextScanner::tryReadSize(std::uint64_t& size) {
  skipSpace();
  const char* first = text_.data() + pos_;
  const auto [ptr, ec] = std::from_chars(first, text_.data() + text_.size(), size);
  if (ec != std::errc{} || ptr == first || !delimiterAt(ptr)) return false;
  pos_ = static_cast<std::size_t>(ptr - text_.data());
  return true;
}

SourceLocation FieldTextScanner::here() const {
  return SourceLocation{file_, line_, static_cast<int>(pos_ - lineStart_) + 1};
}

std::string FieldTextScanner::describeNext() const {
  if (atEnd()) return "the end of the file";
  const char c = text_[pos_];
  if (c == '(' || c == ')' || c == '{' || c == '}' || c == ';') return fmt::format("'{}'", c);
  std::size_t end = pos_;
  while (end < text_.size() && end - pos_ < 40 && !delimiterAt(text_.data() + end)) ++end;
  std::string token(text_.substr(pos_, end - pos_));
  for (char& ch : token) {
    if (static_cast<unsigned char>(ch) < 0x20 || static_cast<unsigned char>(ch) >= 0x7f) ch = '?';
  }
  return fmt::format("'{}'{}", token, end - pos_ >= 40 ? "..." : "");
}

void FieldTextScanner::error(std::string message) const {
  std::string where;
  if (!context_.empty()) where = context_;
  if (count_ > 0) {
    where += fmt::format("{}value {}", where.empty() ? "" : ", ", element_ + 1);
    if (count_ != unknownCount) where += fmt::format(" of {}", count_);
  }
  fatalIOError(here(), where.empty() ? std::move(message) : fmt::format("{}: {}", where, message));
}

void FieldTextScanner::expected(std::string_view what) const {
  error(fmt::format("expected {}, found {}", what, describeNext()));
}

void FieldTextScanner::outOfRange(std::string_view what) const {
  error(fmt::format("expected {}, found {}, which is out of range", what, describeNext()));
}

void FieldTextScanner::notFinite(std::string_view what) const {
  error(fmt::format("{} is not a finite number; expected {}", describeNext(), what));
}

double FieldTextScanner::outOfRangeScalar(std::size_t first, const char* last, std::string_view what) const {
  const std::string number(text_.data() + first, last);
  const double v = std::strtod(number.c_str(), nullptr);
  if (!std::isfinite(v)) notFinite(what);
  return v;
}

}  // namespace isph
