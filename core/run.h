#pragma once
// One recorded (or simulated) insertion run: metadata plus sample columns.
//
// Sign conventions (thesis, models.md): position grows as the needle goes deeper;
// force is positive when the tissue pushes back against insertion.

#include <QHash>
#include <QString>
#include <cstddef>
#include <map>
#include <optional>
#include <utility>
#include <vector>

namespace nb {

// Ordered `key: value` metadata, as written in the run file's `# key: value` lines.
class Metadata {
public:
    std::optional<QString> value(const QString& key) const;
    QString value(const QString& key, const QString& fallback) const;
    std::optional<double> number(const QString& key) const;
    void set(const QString& key, const QString& value);
    void set(const QString& key, double value);
    void remove(const QString& key);
    bool contains(const QString& key) const { return value(key).has_value(); }
    const std::vector<std::pair<QString, QString>>& entries() const { return entries_; }
    bool empty() const { return entries_.empty(); }

private:
    std::vector<std::pair<QString, QString>> entries_;
    // Key -> position in entries_: a file with many metadata lines is read in linear time.
    QHash<QString, std::size_t> index_;
};

struct Run {
    // Metadata lines before the header; `footer` holds those after the data (written at
    // the end of a recording: end reason, dropped samples), so a crashed recording keeps
    // its samples and simply lacks a footer.
    Metadata metadata;
    Metadata footer;

    std::vector<double> time_s;
    std::vector<double> position_mm;
    std::vector<double> force_N;

    // Optional columns kept by name, in file order (e.g. velocity_mm_s, voltage_V, seq).
    std::vector<std::pair<QString, std::vector<double>>> numeric;
    // Optional text columns (e.g. phase).
    std::vector<std::pair<QString, std::vector<QString>>> text;

    std::size_t size() const { return time_s.size(); }
    const std::vector<double>* numericColumn(const QString& name) const;
    std::vector<double>& addNumericColumn(const QString& name);
    const std::vector<QString>* textColumn(const QString& name) const;
    std::vector<QString>& addTextColumn(const QString& name);

    // Looks a key up in the footer first (it is written last and wins), then the header.
    std::optional<QString> meta(const QString& key) const;
};

}  // namespace nb
