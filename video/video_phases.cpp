#include "video_phases.h"

#include "frame_reader.h"

#include "core/label_suggest.h"

#include <cmath>
#include <stdexcept>

namespace nb::video {

VideoPhases suggestPhasesFromVideo(const FrameIndex& index, const Run& run, const VideoSyncOptions& options)
{
    VideoPhases out;
    VideoSync vs;
    try {
        vs = syncVideoToRun(index, run, options);
    } catch (const std::invalid_argument& e) {
        out.labels = suggestLabels(run);
        out.note = QString::fromUtf8(e.what());
        return out;
    }
    out.sync = vs.result;
    if (!vs.result.acceptable() || vs.track.time_s.empty() || vs.result.scale_px_per_mm == 0.0) {
        out.labels = suggestLabels(run);
        out.note = QStringLiteral("the video could not be synchronised with confidence (%1)").arg(vs.result.confidence, 0, 'f', 2);
        return out;
    }
    FrameReader reader(index, 8);
    const NeedleTrack tissue = trackBeside(reader, vs.track.axis);
    std::vector<double> time_s(tissue.time_s.size()), tissue_mm(tissue.time_s.size());
    const TimelineMapping mapping = vs.result.mapping();
    for (std::size_t k = 0; k < tissue.time_s.size(); ++k) {
        time_s[k] = mapping.toRecording(tissue.time_s[k]);
        tissue_mm[k] = tissue.displacement_px[k] / vs.result.scale_px_per_mm;
    }
    out.labels = suggestPhaseLabelsFromTissue(run, time_s, tissue_mm);
    out.fromVideo = true;
    return out;
}

}  // namespace nb::video
