#pragma once
// The experiment plan's dock (issue 16): progress ("Run 7 of 21 · about 12 min left"), the
// next run and its settings, the checklist that must be ticked before Start, skip and redo with
// a reason, leave / return to the plan, and the list of runs with their status. It only shows
// and asks; the window's plan walker decides.

#include <QDialog>
#include <QString>
#include <QStringList>
#include <QWidget>

class QCheckBox;
class QLabel;
class QLineEdit;
class QListWidget;
class QPushButton;
class QComboBox;
class QSpinBox;

namespace nb {

struct PlanPanelView {
    bool hasPlan = false;
    bool walking = false;       // settings locked in the control panel
    bool recording = false;     // a plan run records: skip, redo and leave wait
    QString title;              // the plan's name
    QString progress;           // "Run 7 of 21 · about 12 min left"
    QString next;               // "Run 7: friction 0.5 Hz site 3"; empty when all are done
    QString settings;           // one line: motion, tissue, tip, seed, stop at puncture
    QString instruction;        // empty: nothing to do by hand
    bool instructionDone = false, biasDone = false, zeroDone = false;
    QStringList runs;           // one line per run with its status
    int nextRow = -1;
    QString redoWhat;           // "Run 6: ..." the run redo would make again; empty: none
};

class PlanPanel : public QWidget {
    Q_OBJECT
public:
    enum class Item { Instruction, Bias, Zero };

    explicit PlanPanel(QWidget* parent = nullptr);
    void setView(const PlanPanelView& view);
    const PlanPanelView& view() const { return view_; }

    QCheckBox* checkBox(Item item) const;
    QPushButton* skipButton() const { return skip_; }
    QPushButton* redoButton() const { return redo_; }
    QPushButton* leaveButton() const { return leave_; }
    QString progressText() const;

signals:
    void itemToggled(nb::PlanPanel::Item item, bool on);
    void skipRequested(const QString& reason);
    void redoRequested(const QString& reason);
    void leaveRequested();
    void rejoinRequested();
    void newPlanRequested();

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    void askReason(const QString& title, const QString& question, void (PlanPanel::*done)(const QString&));

    PlanPanelView view_;
    QLabel* title_ = nullptr;
    QLabel* progress_ = nullptr;
    QLabel* next_ = nullptr;
    QLabel* settings_ = nullptr;
    QCheckBox* instruction_ = nullptr;
    QLabel* instructionText_ = nullptr;  // wraps: a template's instruction is the window's longest line
    QCheckBox* bias_ = nullptr;
    QCheckBox* zero_ = nullptr;
    QPushButton* skip_ = nullptr;
    QPushButton* redo_ = nullptr;
    QPushButton* leave_ = nullptr;
    QPushButton* newPlan_ = nullptr;
    QListWidget* runs_ = nullptr;
    QWidget* walker_ = nullptr;
    QLabel* empty_ = nullptr;
};

// Asks why a run is skipped or made again; OK only with a reason. Opened window-modal with
// open(), so Esc and the emergency stop's filter keep working.
class PlanReasonDialog : public QDialog {
    Q_OBJECT
public:
    PlanReasonDialog(const QString& title, const QString& question, QWidget* parent = nullptr);
    QString reason() const;
    QLineEdit* edit() const { return edit_; }

private:
    QLineEdit* edit_ = nullptr;
};

// Session ▸ New plan from template…: a template, the order and its seed.
class NewPlanDialog : public QDialog {
    Q_OBJECT
public:
    explicit NewPlanDialog(QWidget* parent = nullptr);
    QString templateName() const;
    QString orderName() const;  // listed | random | blocked
    quint64 seed() const;
    void setTemplate(const QString& name);
    void setOrder(const QString& name);

private:
    QComboBox* template_ = nullptr;
    QComboBox* order_ = nullptr;
    QSpinBox* seed_ = nullptr;
    QLabel* description_ = nullptr;
};

}  // namespace nb
