#pragma once
// Translation contexts for code outside QObject classes: write `nb::TrCli::tr("...")`, always
// qualified. Each context is named after its struct, which is also what lupdate files the
// string under, so the .ts files and the run-time look-up agree (a local tr() wrapper in a
// namespace would be filed under the namespace and never found at run time).

#include <QCoreApplication>

namespace nb {

struct TrCore {
    Q_DECLARE_TR_FUNCTIONS(nb::TrCore)
};
struct TrDevices {
    Q_DECLARE_TR_FUNCTIONS(nb::TrDevices)
};
struct TrCli {
    Q_DECLARE_TR_FUNCTIONS(nb::TrCli)
};
struct TrViews {
    Q_DECLARE_TR_FUNCTIONS(nb::TrViews)
};

}  // namespace nb
