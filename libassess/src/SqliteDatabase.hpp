#pragma once
// A thin RAII layer over SQLite's C API for the campaign store: a connection, prepared statements
// with typed binds and columns, and a transaction that rolls back unless committed. Every failure
// is an InputError naming the database file and SQLite's own message.
#include <cstdint>
#include <memory>
#include <optional>
#include <string>

struct sqlite3;
struct sqlite3_stmt;

namespace sylva::assess {

class SqliteStatement;

class SqliteDatabase {
public:
    // Opens (creating it if `create`) the database at `path`. Opening does not read the file:
    // a file that is not a database is reported by the first statement.
    SqliteDatabase(std::string path, bool create);
    ~SqliteDatabase();
    SqliteDatabase(const SqliteDatabase&) = delete;
    SqliteDatabase& operator=(const SqliteDatabase&) = delete;

    void execute(const std::string& sql);  // one or more statements without results
    SqliteStatement prepare(const std::string& sql);
    [[noreturn]] void fail(const std::string& what) const;  // InputError with SQLite's last message

private:
    std::string path_;
    sqlite3* db_ = nullptr;
};

class SqliteStatement {
public:
    SqliteStatement(SqliteDatabase& db, sqlite3_stmt* statement) : db_(&db), statement_(statement) {}
    SqliteStatement(SqliteStatement&& other) noexcept;
    ~SqliteStatement();

    // Binds by position (1-based); NaN is stored as NULL, which is how SQLite keeps it anyway.
    SqliteStatement& bind(int index, double value);
    SqliteStatement& bind(int index, std::int64_t value);
    SqliteStatement& bind(int index, const std::string& text);
    SqliteStatement& bindNull(int index);
    SqliteStatement& bindBlob(int index, const std::string& bytes);
    // Runs to the next row: true while there is one. Resets itself (keeping the binds) when done.
    bool step();
    void run();  // a statement without results

    double real(int column) const;  // NULL reads back as NaN
    std::int64_t integer(int column) const;
    std::string text(int column) const;
    std::string blob(int column) const;

private:
    bool isNull(int column) const;
    SqliteDatabase* db_;
    sqlite3_stmt* statement_;
};

// BEGIN IMMEDIATE ... COMMIT; destroyed before commit() it rolls back, so an exception leaves the
// database as it was.
class SqliteTransaction {
public:
    explicit SqliteTransaction(SqliteDatabase& db);
    ~SqliteTransaction();
    SqliteTransaction(const SqliteTransaction&) = delete;
    SqliteTransaction& operator=(const SqliteTransaction&) = delete;
    void commit();

private:
    SqliteDatabase& db_;
    bool open_ = true;
};

}  // namespace sylva::assess
