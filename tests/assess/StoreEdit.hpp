#pragma once
// Edits a campaign store's database with SQL, outside sylvarock, as a user with sqlite3 (or a
// damaged disk) would: what the store's tests use to leave the traces of kills and edits.
#include <gtest/gtest.h>
#include <sqlite3.h>

#include <string>

inline void editStore(const std::string& path, const std::string& sql) {
    sqlite3* db = nullptr;
    ASSERT_EQ(sqlite3_open(path.c_str(), &db), SQLITE_OK);
    char* error = nullptr;
    const int rc = sqlite3_exec(db, sql.c_str(), nullptr, nullptr, &error);
    const std::string why = error ? error : "";
    sqlite3_free(error);
    sqlite3_close(db);
    ASSERT_EQ(rc, SQLITE_OK) << why;
}
