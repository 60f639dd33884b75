// Reading CSV tables (RFC 4180: comma-separated, fields optionally in double quotes with ""
// for a quote, quoted fields may span lines; CRLF or LF; a UTF-8 BOM is ignored).
#pragma once

#include <string>
#include <vector>

namespace maquette {

struct CsvRow {
  int line = 0;  // 1-based line of the file where the row starts
  std::vector<std::string> fields;
};

struct CsvTable {
  std::vector<std::string> columns;  // the header line
  std::vector<CsvRow> rows;          // blank lines skipped
};

// Throws maquette::Error naming the file (and line): unreadable, empty, an unterminated quote,
// a row whose field count differs from the header's.
CsvTable read_csv(const std::string& path);

}  // namespace maquette
