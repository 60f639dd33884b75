#include "vector/csv_table.h"

#include "core/error.h"
#include "core/json_file.h"

namespace maquette {
namespace {

std::string read_text(const std::string& path) {
  std::string s = read_text_file(path);
  if (s.starts_with("\xEF\xBB\xBF")) s.erase(0, 3);
  return s;
}

// Splits the text into records of fields; each record remembers the line it starts on.
std::vector<CsvRow> parse_records(const std::string& text, const std::string& path) {
  std::vector<CsvRow> records;
  CsvRow record{1, {}};
  std::string field;
  bool quoted = false, record_has_data = false;
  int line = 1, quote_line = 0;
  auto end_record = [&] {
    if (record_has_data) {
      record.fields.push_back(std::move(field));
      records.push_back(std::move(record));
    }
    field.clear();
    record = {line, {}};
    record_has_data = false;
  };
  for (size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (quoted) {
      if (c == '"' && i + 1 < text.size() && text[i + 1] == '"') {
        field += '"';
        ++i;
      } else if (c == '"') {
        quoted = false;
      } else {
        if (c == '\n') ++line;
        field += c;
      }
    } else if (c == '"') {
      quoted = true;
      quote_line = line;
      record_has_data = true;
    } else if (c == ',') {
      record.fields.push_back(std::move(field));
      field.clear();
      record_has_data = true;
    } else if (c == '\n') {
      ++line;
      end_record();
    } else if (c != '\r') {
      field += c;
      record_has_data = true;
    }
  }
  if (quoted)
    throw Error(path + " line " + std::to_string(quote_line) + ": unterminated quoted field");
  end_record();
  return records;
}

}  // namespace

CsvTable read_csv(const std::string& path) {
  std::vector<CsvRow> records = parse_records(read_text(path), path);
  if (records.empty()) throw Error(path + " is empty: expected a header line");
  CsvTable table{std::move(records.front().fields), {}};
  for (size_t r = 1; r < records.size(); ++r) {
    if (records[r].fields.size() != table.columns.size())
      throw Error(path + " line " + std::to_string(records[r].line) + ": " +
                  std::to_string(records[r].fields.size()) + " fields, the header has " +
                  std::to_string(table.columns.size()));
    table.rows.push_back(std::move(records[r]));
  }
  return table;
}

}  // namespace maquette
