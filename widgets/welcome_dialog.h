#pragma once
// The first thing a new operator sees when no session is open: start a new session, open one,
// or pick one of the recent ones. Nothing is created on disk until they choose.

#include <QDialog>
#include <QStringList>

class QListWidget;

namespace nb {

class WelcomeDialog : public QDialog {
    Q_OBJECT
public:
    // `recent`: session folders, newest first (those no longer sessions are not shown).
    explicit WelcomeDialog(const QStringList& recent, QWidget* parent = nullptr);
    QListWidget* recentList() const { return recent_; }

signals:
    void newSessionRequested();
    void openSessionRequested();
    void recentSessionChosen(const QString& dir);

private:
    QListWidget* recent_;
};

}  // namespace nb
