#include "kresling/model/family_table.hpp"

#include <algorithm>
#include <stdexcept>

namespace kresling::model {

Column real_column(std::vector<double> values, Index width) {
  Column c;
  c.width = width;
  c.reals = std::move(values);
  return c;
}

Column index_column(std::vector<Index> values, Index width) {
  Column c;
  c.width = width;
  c.integer = true;
  c.indices = std::move(values);
  return c;
}

const Column& require_column(const Table& table, const std::string& family,
                             const std::string& name, bool integer, Index width, Index rows) {
  const auto it = table.find(name);
  const std::string where = family + "." + name;
  if (it == table.end()) throw std::invalid_argument(where + ": missing (the family needs it)");
  const Column& c = it->second;
  if (c.integer != integer) {
    throw std::invalid_argument(where + ": must hold " +
                                (integer ? "node indices (integers)" : "real numbers"));
  }
  if (width > 0 && (c.width != width || c.size() % width != 0)) {
    throw std::invalid_argument(where + ": must have " + std::to_string(width) +
                                " entries per element");
  }
  if (rows >= 0 && width > 0 && c.size() / width != rows) {
    throw std::invalid_argument(where + ": has " + std::to_string(c.size() / width) +
                                " rows, must have one per element (" + std::to_string(rows) + ")");
  }
  return c;
}

Index column_rows(const Table& table, const std::string& family, const std::string& name,
                  bool integer, Index width) {
  return require_column(table, family, name, integer, width).size() / width;
}

void require_known_columns(const Table& table, const std::string& family,
                           const std::vector<std::string>& known) {
  for (const auto& [name, column] : table) {
    if (std::find(known.begin(), known.end(), name) == known.end()) {
      std::string allowed;
      for (const auto& k : known) allowed += (allowed.empty() ? "" : ", ") + k;
      throw std::invalid_argument(family + "." + name + ": unknown column (the family has " +
                                  allowed + ")");
    }
  }
}

}  // namespace kresling::model
