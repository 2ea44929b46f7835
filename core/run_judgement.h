#pragma once
// Which runs an analysis may take as whole insertions. A run cut short (force limit,
// emergency stop, fault, ...) ends where the protection acted, not where the tissue gave way,
// so its "puncture" is the stop; a run that never touched tissue has no stiffness and no
// friction to fit. Such runs are left out unless the operator asks for them, always saying why.
// Among the runs kept, a value far from the others by a robust rule (median and MAD, so the odd
// run cannot hide itself by pulling the mean) is flagged with the rule that flagged it.

#include "core/run.h"

#include <QString>
#include <QStringList>
#include <vector>

namespace nb {

struct RunJudgement {
    bool usable = true;
    QString reason;  // why it is left out (translated); empty when usable
};

// The footer's end reason (force limit, emergency stop, fault, write error, interrupted,
// aborted, recovered without a footer, or no footer at all) and tissue contact.
RunJudgement judgeRun(const Run& run);

// The force rose clearly out of its noise at some point: its robust span (1st to 99th
// percentile) exceeds both kMinContact_N and 8 noise sigmas (the noise from the MAD of
// sample-to-sample differences).
constexpr double kMinContact_N = 0.03;
bool touchedTissue(const Run& run);

// For each value, why it is an outlier (empty when it is not): further from the median than
// `k` scaled MADs (1.4826·MAD) and than `relativeFloor`·|median| (near-identical runs have a
// tiny MAD). Needs at least `minValues` values; fewer say nothing.
QStringList robustOutlierReasons(const std::vector<double>& values, const QString& quantity, const QString& unit,
                                 double k = 3.0, double relativeFloor = 0.15, std::size_t minValues = 4);

}  // namespace nb
