#pragma once
// Shows the current video frame, scaled to fit with its aspect kept, with frame number and
// time. The operator marks the picture for the sync: a drag draws the region the needle is read
// in, a drag with Shift held the needle's line (when the picture does not show it plainly enough
// to be found); a click, or a Shift-click, clears either.

#include "core/run_video_link.h"

#include <QImage>
#include <QLineF>
#include <QRect>
#include <QWidget>

class QPushButton;

namespace nb {

class VideoView : public QWidget {
    Q_OBJECT
public:
    explicit VideoView(QWidget* parent = nullptr);
    // `note` follows the frame number and time, in amber: something the operator should know
    // about this picture (that the decoder made part of it up).
    void setFrame(const QImage& image, int index, double time_s, const QString& note = {});
    void setMessage(const QString& text);  // shown instead of a frame (no video, indexing...)
    QString message() const { return message_; }
    QString note() const { return note_; }
    QRect roi() const { return marks_.region; }     // in video pixels; empty = whole frame
    void setRoi(const QRect& roi);
    QLineF needleLine() const { return marks_.needle; }  // in video pixels; null = find it in the picture
    void setNeedleLine(const QLineF& line);
    PictureMarks marks() const { return marks_; }
    void setMarks(const PictureMarks& marks);
    // Where the frame is drawn in the view (its aspect kept).
    QRect pictureRect() const;
    int frameIndex() const { return index_; }
    QSize sizeHint() const override { return {480, 320}; }
    // Back to the "No video" placeholder with its Open video… button.
    void clearVideo();
    QPushButton* openButton() const { return openButton_; }

signals:
    void marksChanged(const PictureMarks& marks);  // the region or the line, drawn or cleared
    void openRequested();                   // the placeholder's Open video… button
    void videoDropped(const QString& path); // a file dropped on the view

protected:
    void resizeEvent(QResizeEvent*) override;
    void dragEnterEvent(QDragEnterEvent*) override;
    void dropEvent(QDropEvent*) override;

    void paintEvent(QPaintEvent*) override;
    void mousePressEvent(QMouseEvent*) override;
    void mouseMoveEvent(QMouseEvent*) override;
    void mouseReleaseEvent(QMouseEvent*) override;

private:
    QPoint toVideo(QPoint widget) const;
    QImage image_;
    int index_ = -1;
    double time_ = 0.0;
    QString note_;
    QString message_;
    PictureMarks marks_;
    QPoint dragStart_;
    enum class Drag { None, Region, Needle } drag_ = Drag::None;
    QPushButton* openButton_ = nullptr;
    void placeOpenButton();
};

}  // namespace nb
