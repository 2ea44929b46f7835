#include "labels_from_video.h"

#include "core/label_suggest.h"
#include "core/tr.h"
#include "frame_reader.h"
#include "surface_trace.h"
#include "tissue_tracker.h"
#include "video_error.h"

#include <algorithm>

namespace nb::video {

bool suggestsPhases(const Run& run, const Labels& suggested)
{
    const QString protocol = run.metadata.value(QStringLiteral("protocol"), QString());
    if (!protocol.isEmpty())
        return protocol == QLatin1String("friction");
    return std::any_of(suggested.begin(), suggested.end(), [](const Label& l) { return l.track != QLatin1String("events"); });
}

VideoLabels suggestLabelsWithVideo(const Run& run, const FrameIndex& index, const TimelineMapping& mapping, const QString& name,
                                   const std::function<void(int, int)>& progress, const std::atomic_bool* cancel)
{
    VideoLabels out;
    out.labels = suggestLabels(run);
    out.phases = suggestsPhases(run, out.labels);
    std::vector<SurfaceTrace> surface;
    try {
        FrameReader reader(index);
        reader.keepGrayFrames(kPassesGrayBudget_bytes);  // the tissue's background, its shifts, the surface
        const TissueShifts shifts = trackTissueShifts(reader, {}, progress, cancel);
        if (cancel && cancel->load()) {
            out.cancelled = true;
            out.problem = nb::TrDevices::tr("stopped before the video was read");
            return out;
        }
        if (out.phases) {
            TissueMotion m = tissueMotionFromShifts(shifts, run, mapping, &out.problem);
            if (!m.time_s.empty()) {
                m.source = name;
                out.tissue = std::move(m);
            }
        } else {
            surface = surfaceTraces(reader, shifts, mapping, name);
            if (surface.empty())
                out.problem = nb::TrDevices::tr("too few distinct frames to follow the surface");
        }
    } catch (const VideoError& e) {
        out.problem = e.message();
    } catch (const std::exception& e) {
        out.problem = QString::fromUtf8(e.what());
    }
    if (out.tissue) {
        out.labels = suggestPhaseLabels(run, &*out.tissue);
        out.videoUsed = true;
        out.problem.clear();
    } else if (!surface.empty()) {
        QString why;
        out.labels = suggestEventLabels(run, surface, &why);
        out.videoUsed = true;
        out.problem.clear();
        const bool relaxed =
            std::any_of(out.labels.begin(), out.labels.end(), [](const Label& l) { return l.label == QLatin1String("relaxation"); });
        out.relaxationProblem = relaxed ? QString() : why;
    } else if (out.problem.isEmpty()) {
        out.problem = nb::TrDevices::tr("the video gave no motion to read");
    }
    return out;
}

}  // namespace nb::video
