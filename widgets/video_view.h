#pragma once
// Shows the current video frame, scaled to fit with its aspect kept, with frame number and
// time; the user drags a rectangle to set the region used for the motion signal (sync).

#include <QImage>
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
    QRect roi() const { return roi_; }     // in video pixels; empty = whole frame
    void setRoi(const QRect& roi);
    int frameIndex() const { return index_; }
    QSize sizeHint() const override { return {480, 320}; }
    // Back to the "No video" placeholder with its Open video… button.
    void clearVideo();
    QPushButton* openButton() const { return openButton_; }

signals:
    void roiChanged(const QRect& roi);
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
    QRect target() const;  // where the frame is drawn
    QPoint toVideo(QPoint widget) const;
    QImage image_;
    int index_ = -1;
    double time_ = 0.0;
    QString note_;
    QString message_;
    QRect roi_;
    QPoint dragStart_;
    bool dragging_ = false;
    QPushButton* openButton_ = nullptr;
    void placeOpenButton();
};

}  // namespace nb
