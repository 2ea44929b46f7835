#pragma once
#include <QCoreApplication>
#include <QString>
#include <QStringList>

namespace nb {

// Languages shipped in translations/ (compiled into the binary).
QStringList availableLanguages();
// The language chosen in the settings ("language"), else the system's; "en" is the source.
QString preferredLanguage();
void setPreferredLanguage(const QString& code);
// Loads the application's and Qt's own translations for preferredLanguage().
void installTranslation(QCoreApplication& app);

}  // namespace nb
