#pragma once
/// \file family_table.hpp
/// An element family's data as named columns: how families cross the Python binding (and
/// any other reader) without each family needing a binding of its own.
///
/// A column has one row per element and `width` entries per row (1 for a scalar per
/// element, 3 for an anchor point, 4 for a hinge's nodes), held row-major, as reals or as
/// node indices. A family with a varying number of nodes per element (a cable) stores them
/// flat in one column and their counts in another.

#include <map>
#include <string>
#include <vector>

#include "kresling/core/types.hpp"

namespace kresling::model {

struct Column {
  Index width = 1;             ///< entries per element
  bool integer = false;        ///< node indices (`indices`) rather than reals (`reals`)
  std::vector<double> reals;   ///< row-major, size() = rows * width, when !integer
  std::vector<Index> indices;  ///< row-major, when integer

  Index size() const { return static_cast<Index>(integer ? indices.size() : reals.size()); }
};

/// Columns by name (ordered, so a table lists the same way every time).
using Table = std::map<std::string, Column>;

Column real_column(std::vector<double> values, Index width = 1);
Column index_column(std::vector<Index> values, Index width = 1);

/// The column `name` of family `family`'s table, checked to hold reals (or node indices when
/// `integer`) in rows of `width` (a ragged column: width 0, any length). `rows` >= 0 also
/// requires that many rows. Throws std::invalid_argument naming the family and column.
const Column& require_column(const Table& table, const std::string& family, const std::string& name,
                             bool integer, Index width, Index rows = -1);

/// The number of rows of `name` (its size over its width), checked as require_column does.
Index column_rows(const Table& table, const std::string& family, const std::string& name,
                  bool integer, Index width);

/// Throws std::invalid_argument naming the first column of `table` not in `known`.
void require_known_columns(const Table& table, const std::string& family,
                           const std::vector<std::string>& known);

}  // namespace kresling::model
