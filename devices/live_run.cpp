#include "live_run.h"

#include "core/events.h"
#include "core/fit_error.h"
#include "core/run_file.h"

#include <algorithm>

namespace nb::devices {

void LiveSeries::clear()
{
    time_s.clear();
    position_mm.clear();
    force_N.clear();
    volts.clear();
}

LiveRun::LiveRun(double keep_s, QObject* parent) : QObject(parent), keep_s_(keep_s) {}

void LiveRun::setSource(SpscRing<Sample>* ring)
{
    if (ring == source_)
        return;
    source_ = ring;
    // Samples of the new devices, timed on the old clock's origin, fell before it: the plots
    // stayed empty at rest for as long as the old clock had run.
    haveSample_ = false;
    recording_ = false;
    startOver();
}

void LiveRun::pull()
{
    drained_.clear();
    if (source_)
        source_->popAll(drained_);
    append(drained_);
    emit pulled();
}

void LiveRun::append(std::span<const Sample> samples)
{
    if (samples.empty())
        return;
    if (!haveSample_) {
        t0_ = samples.front().time_s;
        haveSample_ = true;
    }
    // Between runs only the recent signal matters; a run keeps every sample.
    if (!recording_ && samples.back().time_s - t0_ > keep_s_) {
        t0_ = samples.front().time_s;
        startOver();
    }
    const std::size_t first = series_.size();
    for (const Sample& s : samples) {
        series_.time_s.push_back(s.time_s - t0_);
        series_.position_mm.push_back(s.position_mm);
        series_.force_N.push_back(s.force_N);
        series_.volts.push_back(s.volts);
    }
    lastDevice_s_ = samples.back().time_s;
    emit samplesAppended(first);

    if (!recording_ || !detector_)
        return;
    const std::size_t n = series_.size() - first;
    const auto events = detector_->feed(std::span(series_.time_s).subspan(first, n),
                                        std::span(series_.position_mm).subspan(first, n),
                                        std::span(series_.force_N).subspan(first, n));
    for (const LiveEvent& e : events)
        marks_.push_back({e.name == QLatin1String("contact") ? LiveMarkKind::Contact : LiveMarkKind::Puncture, e.time_s});
    if (!events.empty())
        emit marksChanged();
}

void LiveRun::startOver()
{
    series_.clear();
    marks_.clear();
    emit reset();
}

void LiveRun::beginRun(bool detectEvents)
{
    recording_ = true;
    t0_ = lastDevice_s_;
    detector_.reset();
    if (detectEvents)
        detector_.emplace();
    startOver();
}

QString LiveRun::endRun(const QString& runPath)
{
    const bool detected = detector_.has_value();
    recording_ = false;
    detector_.reset();
    if (!detected || runPath.isEmpty())
        return {};
    Run run;
    try {
        run = readRunFile(runPath).run;
    } catch (const RunFileError& e) {
        return e.message();
    }
    if (run.size() == 0)
        return {};
    try {
        const InsertionEvents events = detectEvents(run);
        // Only a puncture that stands out from the run is marked (the start of a move gives
        // small inertial wiggles that are not one).
        const double peak = *std::max_element(run.force_N.begin(), run.force_N.end()) - events.zeroOffset_N;
        if (events.puncture.force_N < std::max(0.1, 0.2 * peak) || events.puncture.position_mm <= events.contact.position_mm)
            return {};
        // The whole run places them better than the live marks did: those give way.
        std::erase_if(marks_, [](const LiveMark& m) {
            return m.kind == LiveMarkKind::Contact || m.kind == LiveMarkKind::Puncture;
        });
        marks_.push_back({LiveMarkKind::Contact, events.contact.time_s});
        marks_.push_back({LiveMarkKind::Puncture, events.puncture.time_s});
        for (const RunEvent& e : events.internalPunctures)
            marks_.push_back({LiveMarkKind::MinorPuncture, e.time_s});
        emit marksChanged();
    } catch (const FitError&) {
        // No puncture in this run (it stopped early or never touched tissue): nothing to mark.
    }
    return {};
}

void LiveRun::mark(LiveMarkKind kind)
{
    marks_.push_back({kind, now_s()});
    emit marksChanged();
}

}  // namespace nb::devices
