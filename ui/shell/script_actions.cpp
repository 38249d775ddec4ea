// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/shell/script_actions.h"

#include <QAction>
#include <QApplication>
#include <QClipboard>
#include <QCoreApplication>
#include <QFileDialog>
#include <QFileInfo>
#include <QMessageBox>
#include <QProgressDialog>
#include <QPushButton>

#include "core/document/document.h"
#include "core/io/project/project_file_tip.h"
#include "ui/commands/history_bridge.h"
#include "ui/shell/notifier.h"
#include "ui/view/depth_layers_builder.h"
#include "ui/view/viewport.h"

namespace ui {

namespace {

/** Depth layers for a script: built in the viewport, which shows the document's camera. */
class ViewportHost final : public core::ScriptHost {
public:
    ViewportHost(Viewport& viewport, DepthLayersBuilder& builder)
        : m_viewport(viewport), m_builder(builder) {}

    core::Status buildDepthLayers(core::Document& doc, const core::View& view) override {
        const core::View shown = m_viewport.view();
        if (shown.width != view.width || shown.height != view.height || shown.view != view.view ||
            shown.proj != view.proj)
            return core::Error{QCoreApplication::translate(
                                   "ui::ScriptActions",
                                   "the script's view (%1×%2) is not the window's (%3×%4); "
                                   "replay it with layerpaint-cli")
                                   .arg(view.width)
                                   .arg(view.height)
                                   .arg(shown.width)
                                   .arg(shown.height)
                                   .toStdString()};
        (void)doc;
        if (!m_builder.buildNow())
            return core::Error{
                QCoreApplication::translate("ui::ScriptActions",
                                            "the depth layers of this view cannot be built")
                    .toStdString()};
        return {};
    }
    void viewChanged(const core::View&) override { m_viewport.cameraMoved(); }
    core::Result<std::shared_ptr<const core::TipImage>> loadTip(const std::string& path) override {
        return core::loadTipImageFile(path);
    }

private:
    Viewport& m_viewport;
    DepthLayersBuilder& m_builder;
};

} // namespace

struct ScriptActions::Job {
    core::Script script;
    bool oneStep = false;
    std::uint64_t mark = 0; // the history's state before the script
    std::size_t next = 0;
    std::unique_ptr<ViewportHost> host;
    std::unique_ptr<core::ScriptRunner> runner;
};

ScriptActions::ScriptActions(core::Document& document, Viewport& viewport,
                             DepthLayersBuilder& builder, Notifier& notifier)
    : QObject(&notifier), m_document(document), m_viewport(viewport), m_builder(builder),
      m_notifier(notifier) {
    m_run = new QAction(tr("Run &Script…"), this);
    m_run->setObjectName(QStringLiteral("actionRunScript"));
    m_run->setStatusTip(tr("Replay a script of painting operations on the open model"));
    connect(m_run, &QAction::triggered, this, &ScriptActions::showRunDialog);

    m_copy = new QAction(tr("Copy Session as &Script"), this);
    m_copy->setObjectName(QStringLiteral("actionCopySession"));
    m_copy->setStatusTip(tr("Copy what you did since opening the model as a script that "
                            "reproduces it (for bug reports and automation)"));
    connect(m_copy, &QAction::triggered, this, [this] {
        QApplication::clipboard()->setText(sessionText());
        m_notifier.showStatus(
            tr("Copied %n operation(s) as a script", nullptr, int(m_document.session().size())),
            5000);
    });

    m_timer.setInterval(0);
    connect(&m_timer, &QTimer::timeout, this, &ScriptActions::step);
}

ScriptActions::~ScriptActions() = default;

QString ScriptActions::sessionText() const {
    const core::Script script = m_document.session().script();
    return QString::fromStdString(core::scriptToJson(script).dump(1));
}

void ScriptActions::showRunDialog() {
    if (isRunning() || m_document.meshSerial() == 0)
        return;
    const QString path =
        QFileDialog::getOpenFileName(m_notifier.dialogParent(), tr("Run Script"), QString(),
                                     tr("Scripts (*.json);;All files (*)"));
    if (path.isEmpty())
        return;
    core::Result<core::Script> script = core::readScript(path.toStdString());
    if (!script) {
        QMessageBox::warning(
            m_notifier.dialogParent(), tr("Run Script"),
            tr("The script cannot be run: %1").arg(QString::fromStdString(script.error())));
        return;
    }
    QMessageBox ask(
        QMessageBox::Question, tr("Run Script"),
        tr("Run %n operation(s) of %1 on the open model?", nullptr, int(script->operations.size()))
            .arg(QFileInfo(path).fileName()),
        QMessageBox::Cancel, m_notifier.dialogParent());
    QPushButton* one = ask.addButton(tr("As &One Undo Step"), QMessageBox::AcceptRole);
    QPushButton* steps = ask.addButton(tr("&Step by Step"), QMessageBox::AcceptRole);
    ask.setDefaultButton(one);
    ask.exec();
    if (ask.clickedButton() == one || ask.clickedButton() == steps)
        run(*script, ask.clickedButton() == one);
}

void ScriptActions::run(const core::Script& script, bool oneStep) {
    if (isRunning())
        return;
    core::Document& doc = m_document;
    m_job = std::make_unique<Job>();
    m_job->script = script;
    m_job->oneStep = oneStep;
    m_job->host = std::make_unique<ViewportHost>(m_viewport, m_builder);
    m_job->runner = std::make_unique<core::ScriptRunner>(doc, *m_job->host, m_viewport.view());
    m_job->mark = doc.history().mark();
    // The script's paint target, as the headless tool applies it (the view is the window's).
    if (script.target && (script.target->kind != doc.paintTargetOptions().kind ||
                          script.target->resolution != doc.paintTargetOptions().resolution)) {
        if (const core::Status s = doc.setPaintTarget(*script.target); !s) {
            finish(QString::fromStdString(s.error()));
            return;
        }
    }
    m_progress = new QProgressDialog(tr("Running the script…"), tr("Cancel"), 0,
                                     int(script.operations.size()), m_notifier.dialogParent());
    m_progress->setWindowModality(Qt::WindowModal);
    m_progress->setMinimumDuration(500);
    connect(m_progress, &QProgressDialog::canceled, this,
            [this] { finish(tr("cancelled after %n operation(s)", nullptr, int(m_job->next))); });
    m_run->setEnabled(false);
    m_timer.start();
}

void ScriptActions::step() {
    if (!m_job)
        return;
    const nlohmann::json& operations = m_job->script.operations;
    if (m_job->next >= operations.size()) {
        finish({});
        return;
    }
    const core::Status status = m_job->runner->run(operations[m_job->next]);
    ++m_job->next;
    if (m_progress)
        m_progress->setValue(int(m_job->next));
    if (!status)
        finish(QString::fromStdString(status.error()));
}

void ScriptActions::finish(const QString& error) {
    m_timer.stop();
    if (!m_job)
        return;
    if (m_job->oneStep)
        m_document.history().squash(m_job->mark, core::StepKind::Script);
    m_job.reset();
    if (m_progress) {
        m_progress->disconnect(this);
        m_progress->close();
        m_progress->deleteLater();
        m_progress = nullptr;
        m_notifier.dialogParent()->activateWindow(); // painting goes on in the window
    }
    m_run->setEnabled(true);
    emit documentStateChanged();
    if (error.isEmpty())
        m_notifier.showStatus(tr("Script finished"), 5000);
    else
        m_notifier.showStatus(tr("Script stopped: %1").arg(error), 10000);
    emit finished(error);
}

} // namespace ui
