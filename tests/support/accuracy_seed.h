#pragma once
// The seed of a test's random draw. CI must not pass or fail by the draw, so a test repeats one
// draw by default (`fixed`, itself drawn at random once, not chosen for the result);
// NB_ACCURACY_SEED=N repeats another and NB_ACCURACY_SEED=random draws afresh. Printed, with
// what it draws, so that any draw can be repeated.

#include <QtTest>

#include <chrono>

namespace nb::test {

inline unsigned accuracySeed(unsigned fixed, const char* what = "seed")
{
    bool ok = false;
    const QString wanted = qEnvironmentVariable("NB_ACCURACY_SEED");
    unsigned seed = wanted.toUInt(&ok);
    if (!ok)
        seed = wanted == QLatin1String("random") ? unsigned(std::chrono::system_clock::now().time_since_epoch().count() % 1000000) : fixed;
    qInfo("%s %u (repeat with NB_ACCURACY_SEED=%u)", what, seed, seed);
    return seed;
}

}  // namespace nb::test
