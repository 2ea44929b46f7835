#include "welcome_dialog.h"

#include "core/session.h"

#include <QDir>
#include <QFileInfo>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QVBoxLayout>

namespace nb {

WelcomeDialog::WelcomeDialog(const QStringList& recent, QWidget* parent) : QDialog(parent)
{
    setObjectName(QStringLiteral("welcomeDialog"));
    setWindowTitle(tr("Welcome to NeedleBench"));
    auto* intro = new QLabel(tr("A session is a folder for one specimen: its calibration, its runs, their videos and labels. "
                                "Start a new one or continue one."), this);
    intro->setWordWrap(true);
    auto* newButton = new QPushButton(tr("&New session…"), this);
    newButton->setObjectName(QStringLiteral("welcomeNew"));
    newButton->setDefault(true);
    auto* openButton = new QPushButton(tr("&Open session folder…"), this);
    openButton->setObjectName(QStringLiteral("welcomeOpen"));
    recent_ = new QListWidget(this);
    recent_->setObjectName(QStringLiteral("welcomeRecent"));
    for (const QString& dir : recent) {
        auto* item = new QListWidgetItem(recent_);
        item->setData(Qt::UserRole, dir);
        if (Session::isSession(dir)) {
            item->setText(QStringLiteral("%1\n%2").arg(QFileInfo(dir).fileName(), QDir::toNativeSeparators(dir)));
            item->setToolTip(QDir::toNativeSeparators(dir));
            continue;
        }
        // A session moved or renamed since is said to be gone, not silently left out: the
        // operator then knows to look for it.
        item->setText(tr("%1 (not found)\n%2").arg(QFileInfo(dir).fileName(), QDir::toNativeSeparators(dir)));
        item->setToolTip(tr("No session is in this folder any more: moved, renamed, or on a drive not connected. "
                            "Open it where it is now with Open session folder…"));
        item->setFlags(Qt::NoItemFlags);
    }
    auto* recentLabel = new QLabel(recent_->count() ? tr("Recent sessions (double-click to open):") : tr("No recent sessions."), this);
    recent_->setVisible(recent_->count() > 0);
    auto* later = new QPushButton(tr("Not now"), this);
    later->setToolTip(tr("look around without a session; runs need one"));

    auto* heading = new QLabel(tr("Welcome to NeedleBench"), this);
    QFont big = heading->font();
    big.setPointSizeF(big.pointSizeF() * 1.4);
    big.setBold(true);
    heading->setFont(big);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(heading);
    layout->addWidget(intro);
    layout->addWidget(newButton);
    layout->addWidget(openButton);
    layout->addWidget(recentLabel);
    layout->addWidget(recent_, 1);
    if (recent_->count() == 0)
        layout->addStretch(1);
    layout->addWidget(later, 0, Qt::AlignRight);
    resize(540, recent_->count() ? 420 : sizeHint().height());

    connect(newButton, &QPushButton::clicked, this, [this] {
        accept();
        emit newSessionRequested();
    });
    connect(openButton, &QPushButton::clicked, this, [this] {
        accept();
        emit openSessionRequested();
    });
    connect(recent_, &QListWidget::itemActivated, this, [this](QListWidgetItem* item) {
        const QString dir = item->data(Qt::UserRole).toString();
        accept();
        emit recentSessionChosen(dir);
    });
    connect(later, &QPushButton::clicked, this, &QDialog::reject);
}

}  // namespace nb
