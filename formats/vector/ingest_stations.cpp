// ingest_stations: a CSV table of points into a JSON artifact (layout in README.md).
#include <algorithm>
#include <charconv>
#include <cmath>
#include <map>

#include "core/error.h"
#include "vector/csv_table.h"
#include "vector/vector_ingest.h"

namespace maquette {
namespace {

using json = nlohmann::json;

std::string trimmed(const std::string& s) {
  const auto first = s.find_first_not_of(" \t");
  if (first == std::string::npos) return {};
  return s.substr(first, s.find_last_not_of(" \t") - first + 1);
}

// The number in a field; nullopt for an empty field or (`valid` false) for text.
std::optional<double> parse_number(const std::string& field, bool& valid) {
  const std::string t = trimmed(field);
  valid = true;
  if (t.empty()) return std::nullopt;
  double v = 0;
  const char* begin = t.data() + (t.starts_with('+') ? 1 : 0);
  const auto [end, ec] = std::from_chars(begin, t.data() + t.size(), v);
  valid = ec == std::errc() && end == t.data() + t.size() && std::isfinite(v);
  return v;
}

// Whether the artifact (JSON) can hold `text`: UTF-8, as nlohmann's writer checks it.
bool is_utf8(const std::string& text) {
  try {
    json(text).dump();
    return true;
  } catch (const json::type_error&) {
    return false;
  }
}

class StationsTable {
 public:
  // Throws "PATH: column N's name is not UTF-8 text" for a header the artifact cannot hold.
  StationsTable(std::string path, CsvTable table)
      : path_(std::move(path)), table_(std::move(table)) {
    for (size_t c = 0; c < table_.columns.size(); ++c)
      if (!is_utf8(table_.columns[c]))
        throw Error(path_ + ": column " + std::to_string(c + 1) + "'s name is not UTF-8 text");
  }

  // Throws "PATH: no column 'x' (columns: a, b)" when `name` is not a column.
  size_t column(const std::string& name) const {
    if (auto i = find(name)) return *i;
    std::string all;
    for (const std::string& c : table_.columns) all += (all.empty() ? "" : ", ") + c;
    throw Error(path_ + ": no column '" + name + "' (columns: " + all + ")");
  }
  std::optional<size_t> find(const std::string& name) const {
    const auto& c = table_.columns;
    const auto it = std::find(c.begin(), c.end(), name);
    return it == c.end() ? std::nullopt : std::optional<size_t>(it - c.begin());
  }

  // The row's number in `col`: nullopt when empty; throws naming file, line and column.
  std::optional<double> number(const CsvRow& row, size_t col) const {
    bool valid = true;
    const auto v = parse_number(row.fields[col], valid);
    if (!valid) throw Error(where(row, col) + "'" + row.fields[col] + "' is not a number");
    return v;
  }
  // Like number(), and the value is required and within [lo, hi].
  double coordinate(const CsvRow& row, size_t col, double lo, double hi) const {
    const auto v = number(row, col);
    if (!v) throw Error(where(row, col) + "empty");
    if (*v < lo || *v > hi)
      throw Error(where(row, col) + row.fields[col] + " is outside " + std::to_string(int(lo)) +
                  ".." + std::to_string(int(hi)));
    return *v;
  }

  // Columns other than `taken` whose non-empty fields are all numbers (at least one).
  std::vector<std::string> numeric_columns(const std::vector<std::optional<size_t>>& taken) const {
    std::vector<std::string> out;
    for (size_t c = 0; c < table_.columns.size(); ++c) {
      if (std::find(taken.begin(), taken.end(), c) != taken.end()) continue;
      bool numeric = true, any = false, valid = true;
      for (const CsvRow& row : table_.rows) {
        any |= parse_number(row.fields[c], valid).has_value();
        numeric &= valid;
      }
      if (numeric && any) out.push_back(table_.columns[c]);
    }
    return out;
  }

  // The row's text in `col` (null when there is no such column); throws naming file, line and
  // column when it is not UTF-8 text.
  json text_or_null(const CsvRow& row, std::optional<size_t> col) const {
    if (!col) return nullptr;
    if (!is_utf8(row.fields[*col])) throw Error(where(row, *col) + "not UTF-8 text");
    return row.fields[*col];
  }

  const std::vector<CsvRow>& rows() const { return table_.rows; }

 private:
  std::string where(const CsvRow& row, size_t col) const {
    return path_ + " line " + std::to_string(row.line) + ": column '" + table_.columns[col] + "': ";
  }

  std::string path_;
  CsvTable table_;
};

json or_null(std::optional<double> v) { return v ? json(*v) : json(nullptr); }

}  // namespace

StationsIngestReport ingest_stations(Store& store, const std::string& csv_path,
                                     const StationsIngestOptions& options) {
  if (options.layer.empty()) throw Error("the stations artifact needs a name (--layer)");
  const StationsTable t(csv_path, read_csv(csv_path));
  const size_t lon = t.column(options.lon_column), lat = t.column(options.lat_column),
               elevation = t.column(options.elevation_column);
  const auto id = t.find(options.id_column), name = t.find(options.name_column);

  StationsIngestReport report;
  report.value_columns = options.value_columns.empty()
                             ? t.numeric_columns({lon, lat, elevation, id, name})
                             : options.value_columns;
  std::vector<size_t> values;
  for (const std::string& c : report.value_columns) values.push_back(t.column(c));
  if (t.rows().empty()) throw Error(csv_path + ": no stations (only a header line)");

  json stations = json::array();
  std::map<std::string, int> id_lines;  // station id -> line where it is first given
  for (const CsvRow& row : t.rows()) {
    if (id && !trimmed(row.fields[*id]).empty()) {
      const std::string key = trimmed(row.fields[*id]);
      if (const auto [it, fresh] = id_lines.emplace(key, row.line); !fresh)
        throw Error(csv_path + " line " + std::to_string(row.line) + ": column '" +
                    options.id_column + "': station id '" + key + "' is already given on line " +
                    std::to_string(it->second));
    }
    json v = json::object();
    for (size_t i = 0; i < values.size(); ++i)
      v[report.value_columns[i]] = or_null(t.number(row, values[i]));
    stations.push_back({{"id", t.text_or_null(row, id)},
                        {"name", t.text_or_null(row, name)},
                        {"lon", t.coordinate(row, lon, -180, 180)},
                        {"lat", t.coordinate(row, lat, -90, 90)},
                        {"elevation", or_null(t.number(row, elevation))},
                        {"values", v}});
  }
  report.stations = int64_t(stations.size());
  const json doc = {{"columns", report.value_columns}, {"stations", stations}};
  const std::string text = doc.dump();
  store.put_artifact(Artifact::FromText(options.layer, text,
                                        {{"kind", "stations"},
                                         {"source", csv_path},
                                         {"stations", report.stations},
                                         {"lon_column", options.lon_column},
                                         {"lat_column", options.lat_column},
                                         {"elevation_column", options.elevation_column}}));
  return report;
}

}  // namespace maquette
