#include "translation.h"

#include <QLibraryInfo>
#include <QLocale>
#include <QSettings>
#include <QTranslator>

namespace nb {

QStringList availableLanguages() { return {QStringLiteral("en"), QStringLiteral("de")}; }

QString preferredLanguage()
{
    const QString chosen = QSettings().value(QStringLiteral("language")).toString();
    if (availableLanguages().contains(chosen))
        return chosen;
    const QString system = QLocale().name().left(2);
    return availableLanguages().contains(system) ? system : QStringLiteral("en");
}

void setPreferredLanguage(const QString& code) { QSettings().setValue(QStringLiteral("language"), code); }

void installTranslation(QCoreApplication& app)
{
    // The language installed before goes: kept, it answered every string the new one leaves to
    // the source (English keeps most so), and a window in English showed German notes.
    const QString ours = QStringLiteral("needlebench-translation");
    for (QTranslator* before : app.findChildren<QTranslator*>(ours, Qt::FindDirectChildrenOnly)) {
        QCoreApplication::removeTranslator(before);
        delete before;
    }
    const QString lang = preferredLanguage();
    // English is the source language; its .qm only holds the plural forms ("1 run", "2 runs").
    auto* own = new QTranslator(&app);
    own->setObjectName(ours);
    if (own->load(QStringLiteral(":/i18n/needlebench_%1.qm").arg(lang)))
        app.installTranslator(own);
    if (lang == QLatin1String("en"))
        return;
    auto* qt = new QTranslator(&app);
    qt->setObjectName(ours);
    if (qt->load(QStringLiteral("qtbase_%1").arg(lang), QLibraryInfo::path(QLibraryInfo::TranslationsPath)))
        app.installTranslator(qt);
}

}  // namespace nb
