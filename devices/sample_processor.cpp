#include "sample_processor.h"

#include "core/models.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace nb::devices {

namespace {
constexpr double kCapsuleDropFraction = 0.5;
}

SampleProcessor::SampleProcessor(double rateHz, bool hostPaced, std::shared_ptr<const GroundTruthSource> truth)
    : rate_(rateHz), hostPaced_(hostPaced), truth_(std::move(truth))
{
}

void SampleProcessor::restartStream()
{
    any_ = false;
    forgetStageHistory();
}

void SampleProcessor::startBias(double window_s)
{
    biasing_ = true;
    biasArmed_ = false;  // the window starts at the next sample, whatever its time
    biasWindow_ = window_s;
    biasSum_ = 0.0;
    biasCount_ = 0;
}

void SampleProcessor::setLimits(double insertion_N, double withdrawal_N)
{
    insertLimit_ = insertion_N;
    withdrawLimit_ = std::max(withdrawal_N, insertion_N);
}

void SampleProcessor::watchPunctures(bool on, LiveEventOptions options)
{
    punctures_ = 0;
    detector_.reset();
    if (on) {
        laterDropFraction_ = options.dropFraction;
        options.dropFraction = std::max(options.dropFraction, kCapsuleDropFraction);
        detector_.emplace(options);
        detectorT0_ = -1.0;
    }
}

double SampleProcessor::positionAt(double t, const StageState& stage) const
{
    // Linear between the last two read-backs; the newest one holds from its time on.
    if (prevStageTime_ >= 0 && stageTime_ > prevStageTime_ && t < stageTime_) {
        const double f = (t - prevStageTime_) / (stageTime_ - prevStageTime_);
        return prevStagePos_ + std::clamp(f, 0.0, 1.0) * (stagePos_ - prevStagePos_);
    }
    return stage.position_mm;
}

double SampleProcessor::margin_N(double force_N) const
{
    // Going in, the stage stops at the limit or where the load cell's reading ends, whichever
    // comes first (it showed 8 N of margin where 7.79 N could be read).
    const double stop = slope_ > 0.0 ? std::min(insertLimit_, readableForce_N(+1)) : insertLimit_;
    switch (guard_) {
    case ForceGuard::Insertion: return stop - force_N;
    case ForceGuard::Withdrawal: return withdrawLimit_ - std::fabs(force_N);
    case ForceGuard::Both:
    case ForceGuard::Off: break;
    }
    return stop - std::fabs(force_N);
}

bool SampleProcessor::overLimit(double force_N, double* limit) const
{
    switch (guard_) {
    case ForceGuard::Off: return false;
    case ForceGuard::Insertion: *limit = insertLimit_; return force_N > insertLimit_;
    case ForceGuard::Withdrawal: *limit = withdrawLimit_; return std::fabs(force_N) > withdrawLimit_;
    case ForceGuard::Both: *limit = insertLimit_; return std::fabs(force_N) > insertLimit_;
    }
    return false;
}

// Within a thousandth of the range of its end: the ADC's last codes (the simulated U6 stops one
// step short of +10 V) and a reading that noise keeps off the very end are both there.
bool SampleProcessor::atRangeEnd(double volts) const
{
    return range_V_ > 0.0 && std::fabs(volts) >= 0.999 * range_V_;
}

double SampleProcessor::readableForce_N(int sign) const
{
    if (range_V_ <= 0.0)
        return std::numeric_limits<double>::infinity();
    if (slope_ <= 0.0)
        return 0.0;
    return std::fabs(forceFromVolts(sign > 0 ? 0.999 * range_V_ : -0.999 * range_V_, v0_, slope_));
}

void SampleProcessor::process(std::span<const VoltageSample> batch, const StageState& stage, double arrival_s,
                              std::vector<Sample>& samples, std::vector<ProcessorEvent>& events)
{
    if (!batch.empty()) {
        prevStagePos_ = stageTime_ >= 0 ? stagePos_ : stage.position_mm;
        prevStageTime_ = stageTime_;
        stageTime_ = batch.back().deviceTime_s;
        stagePos_ = stage.position_mm;
    }
    const double period = 1.0 / rate_;
    for (const VoltageSample& v : batch) {
        if (any_ && v.index > expected_)
            counters_.dropped += v.index - expected_;
        expected_ = v.index + 1;
        if (!any_ || arrival_s - v.deviceTime_s < hostOrigin_)
            hostOrigin_ = arrival_s - v.deviceTime_s;
        any_ = true;
        if (hostPaced_ && arrival_s - hostOrigin_ - v.deviceTime_s > period)
            ++counters_.late;
        ++counters_.samples;
        lastTime_ = v.deviceTime_s;

        Sample out;
        out.seq = v.index;
        out.time_s = v.deviceTime_s;
        out.volts = v.volts;
        out.position_mm = positionAt(v.deviceTime_s, stage);
        out.velocity_mm_s = stage.velocity_mm_s;
        out.force_N = slope_ > 0 ? forceFromVolts(v.volts, v0_, slope_) : 0.0;

        if (biasing_) {
            if (!biasArmed_) {
                biasArmed_ = true;
                biasEnd_ = v.deviceTime_s + biasWindow_;
            }
            biasSum_ += v.volts;
            ++biasCount_;
            if (v.deviceTime_s >= biasEnd_) {
                v0_ = biasSum_ / static_cast<double>(biasCount_);
                biasing_ = false;
                biased_ = true;
                // This sample is the first in the new tare, so nothing reads it as loaded.
                out.force_N = slope_ > 0 ? forceFromVolts(v.volts, v0_, slope_) : 0.0;
                ProcessorEvent e{ProcessorEvent::Kind::BiasDone};
                e.time_s = v.deviceTime_s;
                e.bias_V = v0_;
                e.count = biasCount_;
                events.push_back(e);
            }
        }

        // The first sample over the guarded limit: before anything else sees it.
        double limit = 0.0;
        // Going deeper, the top of the range; in a sine or at rest, either end. Not while the
        // needle comes out: a reading stuck at the end would stop every withdrawal again.
        const bool overRange = (guard_ == ForceGuard::Insertion && v.volts > 0.0 && atRangeEnd(v.volts))
                               || (guard_ == ForceGuard::Both && atRangeEnd(v.volts));
        if (biased_ && !tripped_ && (overLimit(out.force_N, &limit) || overRange)) {
            tripped_ = true;
            ProcessorEvent e{ProcessorEvent::Kind::ForceLimit};
            e.time_s = v.deviceTime_s;
            e.force_N = out.force_N;
            e.position_mm = out.position_mm;
            e.limit_N = limit;
            e.overRange = overRange && !overLimit(out.force_N, &limit);
            if (e.overRange)
                e.limit_N = out.force_N;
            events.push_back(e);
        }

        if (detector_) {
            if (detectorT0_ < 0)
                detectorT0_ = v.deviceTime_s;
            const double t = v.deviceTime_s - detectorT0_;
            for (const LiveEvent& le : detector_->feed(std::span(&t, 1), std::span(&out.position_mm, 1), std::span(&out.force_N, 1))) {
                const bool puncture = le.name == QLatin1String("puncture");
                ProcessorEvent e{puncture ? ProcessorEvent::Kind::Puncture : ProcessorEvent::Kind::Contact};
                e.time_s = le.time_s + detectorT0_;
                e.force_N = le.force_N;
                e.position_mm = le.position_mm;
                if (puncture) {
                    e.count = static_cast<std::uint64_t>(++punctures_);
                    detector_->continueAfterPuncture();
                    detector_->setDropFraction(laterDropFraction_);
                }
                events.push_back(e);
            }
        }

        if (truth_) {
            const SampleTruth t = truth_->sampleTruth(v.index);
            out.tissue_position_mm = t.tissue_mm;
            out.phase = t.phase;
        }
        last_ = out;
        samples.push_back(out);
    }
}

}  // namespace nb::devices
