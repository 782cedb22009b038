// MarkdownTable: a header, a separator row, the rows.
#include "clothbench/experiments/markdown_table.hpp"

#include <sstream>

namespace clothbench {

std::string MarkdownTable::str() const {
  std::ostringstream s;
  const auto line = [&](const std::vector<std::string>& cells) {
    s << "|";
    for (const auto& c : cells) s << " " << c << " |";
    s << "\n";
  };
  line(header_);
  s << "|";
  for (std::size_t i = 0; i < header_.size(); ++i) s << "---|";
  s << "\n";
  for (const auto& r : rows_) line(r);
  return s.str();
}

}  // namespace clothbench
