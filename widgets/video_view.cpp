#include "video_view.h"

#include <algorithm>
#include <utility>

#include <QLocale>

#include <QDragEnterEvent>
#include <QDropEvent>
#include <QMimeData>
#include <QMouseEvent>
#include <QPainter>
#include <QPushButton>

namespace nb {

VideoView::VideoView(QWidget* parent) : QWidget(parent)
{
    setMinimumSize(240, 160);
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);
    setAcceptDrops(true);
    openButton_ = new QPushButton(tr("Open video…"), this);
    openButton_->setObjectName(QStringLiteral("openVideoButton"));
    openButton_->setToolTip(tr("attach the video filmed during this run (or drop the file here)"));
    openButton_->setFocusPolicy(Qt::NoFocus);
    connect(openButton_, &QPushButton::clicked, this, &VideoView::openRequested);
    clearVideo();
}

void VideoView::clearVideo()
{
    image_ = QImage();
    index_ = -1;
    message_ = tr("No video. Open one, or drop the file here, to review it with the force record.");
    openButton_->show();
    placeOpenButton();
    update();
}

void VideoView::placeOpenButton()
{
    const QSize s = openButton_->sizeHint();
    openButton_->setGeometry((width() - s.width()) / 2, height() / 2 + fontMetrics().height() * 2, s.width(), s.height());
}

void VideoView::resizeEvent(QResizeEvent*) { placeOpenButton(); }

void VideoView::dragEnterEvent(QDragEnterEvent* e)
{
    const QList<QUrl> urls = e->mimeData()->urls();
    if (urls.size() == 1 && urls.front().isLocalFile())
        e->acceptProposedAction();
}

void VideoView::dropEvent(QDropEvent* e)
{
    const QList<QUrl> urls = e->mimeData()->urls();
    if (urls.size() == 1 && urls.front().isLocalFile()) {
        e->acceptProposedAction();
        emit videoDropped(urls.front().toLocalFile());
    }
}

void VideoView::setFrame(const QImage& image, int index, double time_s, const QString& note)
{
    image_ = image;
    index_ = index;
    time_ = time_s;
    note_ = note;
    message_.clear();
    openButton_->hide();
    update();
}

void VideoView::setMessage(const QString& text)
{
    message_ = text;
    placeOpenButton();
    update();
}

void VideoView::setRoi(const QRect& roi)
{
    setMarks({roi, marks_.needle});
}

void VideoView::setNeedleLine(const QLineF& line)
{
    setMarks({marks_.region, line});
}

void VideoView::setMarks(const PictureMarks& m)
{
    marks_ = m;
    update();
    emit marksChanged(marks_);
}

QRect VideoView::pictureRect() const
{
    if (image_.isNull())
        return rect();
    const QSize s = image_.size().scaled(size(), Qt::KeepAspectRatio);
    return QRect(QPoint((width() - s.width()) / 2, (height() - s.height()) / 2), s);
}

QPoint VideoView::toVideo(QPoint w) const
{
    const QRect t = pictureRect();
    if (image_.isNull() || t.width() == 0 || t.height() == 0)
        return {};
    return {int((w.x() - t.x()) * double(image_.width()) / t.width()), int((w.y() - t.y()) * double(image_.height()) / t.height())};
}

void VideoView::paintEvent(QPaintEvent*)
{
    QPainter p(this);
    p.fillRect(rect(), Qt::black);
    if (!message_.isEmpty() || image_.isNull()) {
        p.setPen(Qt::lightGray);
        p.drawText(rect(), Qt::AlignCenter | Qt::TextWordWrap, message_);
        return;
    }
    const QRect t = pictureRect();
    p.setRenderHint(QPainter::SmoothPixmapTransform);
    p.drawImage(t, image_);
    const double sx = double(t.width()) / image_.width(), sy = double(t.height()) / image_.height();  // video px to view px
    if (const QRect& r = marks_.region; !r.isEmpty()) {
        p.setPen(QPen(QColor(255, 200, 0), 1, Qt::DashLine));
        p.drawRect(QRectF(t.x() + r.x() * sx, t.y() + r.y() * sy, r.width() * sx, r.height() * sy));
    }
    if (const QLineF& n = marks_.needle; !n.isNull()) {
        const QPointF a(t.x() + n.x1() * sx, t.y() + n.y1() * sy), b(t.x() + n.x2() * sx, t.y() + n.y2() * sy);
        p.setRenderHint(QPainter::Antialiasing);
        // Thin and see-through: the operator lays it on the needle and must see the needle under it.
        const QColor cyan(0, 220, 255, 190);
        p.setPen(QPen(cyan, 1.2));
        p.drawLine(a, b);
        p.setBrush(cyan);
        p.drawEllipse(a, 3, 3);
        p.drawEllipse(b, 3, 3);
        p.setBrush(Qt::NoBrush);
    }
    const QString caption = tr("frame %1   %2 s").arg(index_).arg(QLocale().toString(time_, 'f', 3));
    const QFontMetrics fm = p.fontMetrics();
    const int lines = note_.isEmpty() ? 1 : 2;
    const QString note = fm.elidedText(note_, Qt::ElideRight, std::max(0, t.width() - 16));  // a small view or a narrow picture
    const int wide = std::max(fm.horizontalAdvance(caption), note.isEmpty() ? 0 : fm.horizontalAdvance(note));
    p.fillRect(QRect(t.x() + 4, t.y() + 4, wide + 8, lines * fm.height() + 4), QColor(0, 0, 0, 150));
    p.setPen(Qt::white);
    p.drawText(t.x() + 8, t.y() + 6 + fm.ascent(), caption);
    if (!note_.isEmpty()) {
        p.setPen(QColor(255, 190, 60));
        p.drawText(t.x() + 8, t.y() + 6 + fm.height() + fm.ascent(), note);
    }
}

void VideoView::mousePressEvent(QMouseEvent* e)
{
    if (image_.isNull())
        return;
    dragStart_ = toVideo(e->position().toPoint());
    drag_ = e->modifiers() & Qt::ShiftModifier ? Drag::Needle : Drag::Region;
}

void VideoView::mouseMoveEvent(QMouseEvent* e)
{
    const QPoint at = toVideo(e->position().toPoint());
    if (drag_ == Drag::Region)
        marks_.region = QRect(dragStart_, at).normalized() & image_.rect();  // drawn as it is dragged, stored on release
    else if (drag_ == Drag::Needle)
        marks_.needle = QLineF(dragStart_, at);
    else
        return;
    update();
}

void VideoView::mouseReleaseEvent(QMouseEvent* e)
{
    const Drag was = std::exchange(drag_, Drag::None);
    const QPoint at = toVideo(e->position().toPoint());
    if (was == Drag::Region) {
        const QRect r = QRect(dragStart_, at).normalized() & image_.rect();
        setRoi(r.width() > 4 && r.height() > 4 ? r : QRect());  // a click clears the region
    } else if (was == Drag::Needle) {
        const QLineF line(dragStart_, at);
        setNeedleLine(line.length() >= 8 ? line : QLineF());  // a Shift-click clears the line
    }
}

}  // namespace nb
