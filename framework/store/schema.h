// The store's SQLite schema (see framework/store/README.md): creation, and the check that a
// file is a Maquette store of a version this code reads.
#pragma once

#include <cstdint>

#include "store/sqlite.h"

namespace maquette {

constexpr int32_t kStoreApplicationId = 0x4D515354;  // "MQST", PRAGMA application_id
// PRAGMA user_version. 2 added features layers, 3 the marks of incomplete layers, 4 the content
// table (blobs of content and model layers, in parts); older stores are read as they are and
// migrated when opened for writing.
constexpr int32_t kStoreSchemaVersion = 4;

// Page size of a new store: larger pages keep 100 kB tile blobs in fewer overflow pages.
constexpr int kStorePageSize = 16384;

// Writes kStoreSchemaVersion as the database's user_version.
void set_version(sqlite::Connection& conn);

// Sets the per-connection pragmas (memory map; synchronous=NORMAL for writers). Waiting for
// another connection's lock is the busy handler's job (sqlite.cpp: polls for up to 60 s).
// A reader of a store older than version 4 gets a temporary view `content` of the content and
// model blobs its tiles and overviews hold, so that it reads them as a version 4 store's.
void configure_connection(sqlite::Connection& conn, bool writer);

// Creates the schema in an empty database (if it is already a Maquette store: migrates an
// older version). Throws "PATH is not a Maquette store" for a foreign database. The journal
// mode is the caller's (Store::open).
void create_schema(sqlite::Connection& conn);

// Throws maquette::Error unless the database is a Maquette store of a readable version.
void check_schema(sqlite::Connection& conn);

}  // namespace maquette
