#include "run.h"

namespace nb {

std::optional<QString> Metadata::value(const QString& key) const
{
    const auto it = index_.constFind(key);
    if (it == index_.constEnd())
        return std::nullopt;
    return entries_[*it].second;
}

QString Metadata::value(const QString& key, const QString& fallback) const
{
    return value(key).value_or(fallback);
}

std::optional<double> Metadata::number(const QString& key) const
{
    const auto v = value(key);
    if (!v)
        return std::nullopt;
    bool ok = false;
    const double d = v->trimmed().toDouble(&ok);
    return ok ? std::optional<double>(d) : std::nullopt;
}

void Metadata::set(const QString& key, const QString& value)
{
    const auto it = index_.constFind(key);
    if (it != index_.constEnd()) {
        entries_[*it].second = value;
        return;
    }
    index_.insert(key, entries_.size());
    entries_.emplace_back(key, value);
}

void Metadata::remove(const QString& key)
{
    const auto it = index_.constFind(key);
    if (it == index_.constEnd())
        return;
    entries_.erase(entries_.begin() + std::ptrdiff_t(*it));
    index_.clear();
    for (std::size_t i = 0; i < entries_.size(); ++i)
        index_.insert(entries_[i].first, i);
}

void Metadata::set(const QString& key, double value)
{
    set(key, QString::number(value, 'g', 12));
}

const std::vector<double>* Run::numericColumn(const QString& name) const
{
    for (const auto& [n, c] : numeric)
        if (n == name)
            return &c;
    return nullptr;
}

std::vector<double>& Run::addNumericColumn(const QString& name)
{
    for (auto& [n, c] : numeric)
        if (n == name)
            return c;
    return numeric.emplace_back(name, std::vector<double>{}).second;
}

const std::vector<QString>* Run::textColumn(const QString& name) const
{
    for (const auto& [n, c] : text)
        if (n == name)
            return &c;
    return nullptr;
}

std::vector<QString>& Run::addTextColumn(const QString& name)
{
    for (auto& [n, c] : text)
        if (n == name)
            return c;
    return text.emplace_back(name, std::vector<QString>{}).second;
}

std::optional<QString> Run::meta(const QString& key) const
{
    if (auto v = footer.value(key))
        return v;
    return metadata.value(key);
}

}  // namespace nb
