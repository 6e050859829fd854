// Responsiveness of the desktop application, measured on the real MainWindow (offscreen) with
// the six-lobe cam at 100,000 samples per turn:
//  BM_EditToRedraw      — from a cell edit (setData on the segment table) until the four
//                         kinematics plots (r, velocity, acceleration, jerk; and the pressure
//                         angle, when shown) have redrawn
//                         with its result (manual time); counter all_views_ms: until the
//                         contour view has too.
//  BM_StreamingEdits    — 200 cell edits at 100 Hz; counters report the longest stall of the
//                         GUI thread and its 99th percentile, measured by a 1 ms probe timer.
//  BM_ComputeProject    — the worker's share of an edit: the whole computation of one request
//                         including the views' plot containers (no GUI involved).
//  BM_FirstPicture      — the same up to the first picture the window draws (the plot levels
//                         a whole-turn view needs); counter refine_ms: the finer levels after.
//  BM_ManySegments      — a split circle of 1,000 to 100,000 arcs: open until drawn, one
//                         replot of the contour view, close (counters open_ms, replot_ms,
//                         close_ms).
//  BM_CursorMove        — one mouse move over the velocity plot: from the event until the three
//                         plots and the contour view have painted the new cursor (manual time).

#include <benchmark/benchmark.h>

#include <QApplication>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QFile>
#include <QMouseEvent>
#include <QTemporaryDir>
#include <QTimer>
#include <algorithm>
#include <map>
#include <vector>

#include "document/commands.h"
#include "engine/compute_engine.h"
#include "engine/memory_reuse.h"
#include "mainwindow.h"
#include "models/segment_table_model.h"
#include "views/contour_view.h"
#include "views/follower_panel.h"
#include "views/kinematics_plots.h"
#include "views/plot_data.h"

#include <qcustomplot.h>

namespace {

constexpr int kSamples = 100'000;

/// The six-lobe window at kSamples; with `follower`, a roller of 2 mm on a swinging arm and the
/// Follower dock (design checks, pressure-angle plot) shown.
std::unique_ptr<cam::MainWindow> makeWindow(bool follower = false) {
    auto window = std::make_unique<cam::MainWindow>();
    const QString problem =
        window->loadFile(QStringLiteral(CAMWRIGHT_EXAMPLES "/six-lobe-arc-cam.cam.json"));
    if (!problem.isEmpty()) std::abort();
    cam::Project p = window->document()->project();
    window->document()->undoStack()->push(new cam::SetSamplesPerTurn(window->document(), kSamples));
    if (follower) {
        cam::FollowerSpec spec;
        spec.type = cam::FollowerType::Roller;
        spec.radius = 2.0;
        spec.motion = cam::FollowerMotion::Oscillating;
        spec.pivot = {60.0, 0.0};
        spec.armLength = 50.0;
        window->document()->undoStack()->push(new cam::SetFollower(window->document(), spec));
        window->findChild<QDockWidget*>("followerDock")->show();
    }
    window->resize(1400, 860);
    window->show();
    if (!window->waitForCurrentResult(20000)) std::abort();
    QCoreApplication::processEvents();
    return window;
}

/// Toggles segment 0 between arc and line: a real table edit that keeps the contour valid.
void editCell(cam::MainWindow& window) {
    cam::SegmentTableModel* model = window.tableModel();
    const QModelIndex type = model->index(0, cam::SegmentTableModel::Type);
    model->setData(type, type.data(Qt::EditRole).toInt() == 0 ? 1 : 0, Qt::EditRole);
}

/// The windows kept from one repetition to the next, closed by main() before the application
/// ends (a window outliving QApplication crashed the bench at exit).
std::map<std::pair<bool, bool>, std::unique_ptr<cam::MainWindow>> keptWindows;

/// A window kept from one repetition to the next: a designer edits the same open project again
/// and again. Made on first use per (follower, warm) and then reused.
cam::MainWindow& editedWindow(bool follower, bool warm) {
    auto& window = keptWindows[{follower, warm}];
    if (!window) window = makeWindow(follower);
    return *window;
}

/// One edit timed from setData until each of `views` has replotted (and, QCustomPlot's
/// default, repainted) with its result: the time until the last of all but the last view, and
/// in `allViewsMs` until the last view too.
double timeOneEdit(cam::MainWindow& window, const std::vector<QCustomPlot*>& views,
                   double& allViewsMs) {
    bool shown = false;
    QElapsedTimer timer;
    std::vector<qint64> redrawnAt(views.size(), -1);
    std::vector<QMetaObject::Connection> connections;
    const std::uint64_t before = window.engine()->latestGeneration();
    connections.push_back(QObject::connect(&window, &cam::MainWindow::resultShown,
                                           [&](const cam::ComputeResultPtr& result) {
                                               shown = shown || result->generation > before;
                                           }));
    // Waits as the window does, asleep between events: a busy loop here took a core from the
    // engine's pool and slowed every edit it timed.
    QEventLoop loop;
    for (std::size_t i = 0; i < views.size(); ++i) {
        connections.push_back(QObject::connect(views[i], &QCustomPlot::afterReplot, [&, i] {
            if (shown && redrawnAt[i] < 0) redrawnAt[i] = timer.nsecsElapsed();
            if (std::find(redrawnAt.begin(), redrawnAt.end(), -1) == redrawnAt.end()) loop.quit();
        }));
    }
    QTimer::singleShot(5000, &loop, &QEventLoop::quit);
    timer.start();
    editCell(window);
    loop.exec();
    for (const auto& c : connections) QObject::disconnect(c);
    const qint64 plots = *std::max_element(redrawnAt.begin(), redrawnAt.end() - 1);
    allViewsMs = static_cast<double>(std::max(redrawnAt.back(), plots)) * 1e-6;
    // Let the coalescing window close and the refinement arrive: every edit is a lone edit.
    QEventLoop idle;
    QTimer::singleShot(80, &idle, &QEventLoop::quit);
    idle.exec();
    return static_cast<double>(plots) * 1e-6;
}

void BM_EditToRedraw(benchmark::State& state) {
    const bool follower = state.range(0) == 1;
    const bool warm = state.range(1) == 1;
    // Warm: one window for all repetitions, edited twice before (arc to line and back: the
    // table's columns have widened, both shapes' tick labels are known). Cold: a window just
    // opened, and its first edit.
    std::unique_ptr<cam::MainWindow> fresh;
    cam::MainWindow& window = warm ? editedWindow(follower, warm) : *(fresh = makeWindow(follower));
    if (warm && window.property("benchWarmed").isNull()) {
        double ignored = 0.0;
        std::vector<QCustomPlot*> all{window.plots()->plot(0), window.contourView()};
        timeOneEdit(window, all, ignored);
        timeOneEdit(window, all, ignored);
        window.setProperty("benchWarmed", true);
    }
    // The plots the time is taken for (the kinematics plots, and the pressure angle when the
    // follower is shown), then the contour view (counter all_views_ms).
    std::vector<QCustomPlot*> views;
    for (int p = 0; p < cam::KinematicsPlots::kPlotCount; ++p)
        views.push_back(window.plots()->plot(p));
    if (follower) views.push_back(window.followerPanel()->pressurePlot());
    views.push_back(window.contourView());
    for (auto _ : state) {
        double allViewsMs = 0.0;
        state.SetIterationTime(timeOneEdit(window, views, allViewsMs) * 1e-3);
        state.counters["all_views_ms"] = allViewsMs;
    }
}
// 40 edits, each timed alone: the median is the figure docs/performance.md reports.
// Args: follower (0: the six-lobe cam as it is; 1: with a swinging roller and the Follower dock
// shown), warm (1: edits of a window edited before; 0: the first edit of a window just opened).
BENCHMARK(BM_EditToRedraw)
    ->ArgsProduct({{0, 1}, {1, 0}})
    ->ArgNames({"follower", "warm"})
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1)
    ->Repetitions(40)
    ->ReportAggregatesOnly(true);

void BM_StreamingEdits(benchmark::State& state) {
    auto window = makeWindow();
    for (auto _ : state) {
        std::vector<double> gaps;
        QElapsedTimer clock;
        clock.start();
        qint64 lastTick = clock.nsecsElapsed();
        QTimer probe;
        probe.setTimerType(Qt::PreciseTimer);
        probe.setInterval(1);
        QObject::connect(&probe, &QTimer::timeout, [&] {
            const qint64 now = clock.nsecsElapsed();
            gaps.push_back(static_cast<double>(now - lastTick) * 1e-6);
            lastTick = now;
        });
        QTimer editor;
        editor.setTimerType(Qt::PreciseTimer);
        editor.setInterval(10);  // 100 Hz
        int edits = 0;
        QEventLoop loop;  // asleep between events, as the window is
        QObject::connect(&editor, &QTimer::timeout, [&] {
            editCell(*window);
            if (++edits == 200) {
                editor.stop();
                loop.quit();
            }
        });
        probe.start();
        editor.start();
        loop.exec();
        window->waitForCurrentResult(20000);
        QCoreApplication::processEvents();
        probe.stop();
        std::sort(gaps.begin(), gaps.end());
        // A gap is the time between two 1 ms probe ticks: the stall is what exceeds the 1 ms.
        state.counters["max_stall_ms"] = std::max(0.0, gaps.back() - 1.0);
        state.counters["p99_stall_ms"] =
            std::max(0.0, gaps[static_cast<std::size_t>(0.99 * (gaps.size() - 1))] - 1.0);
        state.counters["results_shown"] = static_cast<double>(window->engine()->latestGeneration());
    }
}
BENCHMARK(BM_StreamingEdits)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1)
    ->Repetitions(3)
    ->ReportAggregatesOnly(false);

/// The six-lobe cam as the window loads it, at `samples` per turn.
std::shared_ptr<const cam::Project> sixLobeProject(std::int64_t samples) {
    auto window = std::make_unique<cam::MainWindow>();
    if (!window->loadFile(QStringLiteral(CAMWRIGHT_EXAMPLES "/six-lobe-arc-cam.cam.json"))
             .isEmpty()) {
        std::abort();
    }
    cam::Project p = window->document()->project();
    p.samplesPerTurn = samples;
    return std::make_shared<const cam::Project>(std::move(p));
}

/// The worker's first picture of an edit (plot levels down to
/// PlotCurves::kFirstPictureBuckets, every sample computed), and then its refinement.
void BM_FirstPicture(benchmark::State& state) {
    const cam::ComputeRequest request{
        1,     sixLobeProject(state.range(0)), cam::PlotAxis::Angle,
        false, cam::TimingMethod::Optimal,     cam::PlotCurves::kFirstPictureBuckets};
    const cam::QcpPlotDataPreparer preparer;
    const std::atomic<bool> cancel{false};
    double refineMs = 0.0;
    for (auto _ : state) {
        auto result = cam::computeProject(request, cancel, &preparer);
        benchmark::DoNotOptimize(result);
        state.PauseTiming();
        QElapsedTimer timer;
        timer.start();
        auto refined = cam::refineResult(*result, cancel, &preparer);
        refineMs = static_cast<double>(timer.nsecsElapsed()) * 1e-6;
        benchmark::DoNotOptimize(refined);
        state.ResumeTiming();
    }
    state.counters["refine_ms"] = refineMs;
}
BENCHMARK(BM_FirstPicture)->Arg(3600)->Arg(100'000)->Arg(1'000'000)->Unit(benchmark::kMillisecond);

void BM_ComputeProject(benchmark::State& state) {
    const cam::ComputeRequest request{1, sixLobeProject(state.range(0)), cam::PlotAxis::Angle};
    const cam::QcpPlotDataPreparer preparer;
    const std::atomic<bool> cancel{false};
    for (auto _ : state) {
        auto result = cam::computeProject(request, cancel, &preparer);
        benchmark::DoNotOptimize(result);
    }
    state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK(BM_ComputeProject)
    ->Arg(3600)
    ->Arg(100'000)
    ->Arg(1'000'000)
    ->Arg(10'000'000)
    ->Unit(benchmark::kMillisecond);

void BM_ReplotViews(benchmark::State& state) {
    auto window = makeWindow();
    std::vector<QCustomPlot*> views = {window->plots()->plot(0), window->plots()->plot(1),
                                       window->plots()->plot(2), window->contourView()};
    for (auto _ : state) {
        QElapsedTimer timer;
        timer.start();
        for (QCustomPlot* v : views) v->replot(QCustomPlot::rpImmediateRefresh);
        state.SetIterationTime(static_cast<double>(timer.nsecsElapsed()) * 1e-9);
    }
    for (std::size_t i = 0; i < views.size(); ++i) {
        state.counters["ms_" + std::to_string(i)] = views[i]->replotTime(true);
    }
}
BENCHMARK(BM_ReplotViews)->UseManualTime()->Unit(benchmark::kMillisecond)->Iterations(20);

/// A circle about (5, 0) of radius 20 (branch "outer": the origin is inside) split into n arcs.
QString writeSplitCircle(const QTemporaryDir& dir, int n) {
    const QString path = dir.filePath(QStringLiteral("split-%1.cam.json").arg(n));
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly)) std::abort();
    QByteArray text = R"({"format": "camwright", "version": 1, "motion": {"period_s": 1},
 "contour": [)";
    for (int k = 0; k < n; ++k) {
        text += k == 0 ? "\n" : ",\n";
        text +=
            QStringLiteral(R"({"type": "arc", "center": [5, 0], "radius": 20, "branch": "outer", )"
                           R"("phi_start": %1, "phi_end": %2})")
                .arg(360.0 * k / n, 0, 'g', 17)
                .arg(k + 1 == n ? 360.0 : 360.0 * (k + 1) / n, 0, 'g', 17)
                .toUtf8();
    }
    text += "]}\n";
    file.write(text);
    return path;
}

/// A contour of many segments in the real window: opening it until its first result is drawn,
/// one full replot of the contour view, and closing the window (at 612d090 closing 10,000
/// segments took more than five minutes: a legend item per segment curve).
void BM_ManySegments(benchmark::State& state) {
    const QTemporaryDir dir;
    const QString path = writeSplitCircle(dir, static_cast<int>(state.range(0)));
    double openMs = 0, replotMs = 0, closeMs = 0;
    for (auto _ : state) {
        QElapsedTimer timer;
        timer.start();
        auto window = std::make_unique<cam::MainWindow>();
        window->resize(1400, 860);
        window->show();
        if (!window->loadFile(path).isEmpty()) std::abort();
        if (!window->waitForCurrentResult(600'000)) std::abort();
        QCoreApplication::processEvents();
        window->contourView()->replot(QCustomPlot::rpImmediateRefresh);
        openMs = static_cast<double>(timer.nsecsElapsed()) * 1e-6;
        timer.restart();
        window->contourView()->replot(QCustomPlot::rpImmediateRefresh);
        replotMs = static_cast<double>(timer.nsecsElapsed()) * 1e-6;
        timer.restart();
        window.reset();
        closeMs = static_cast<double>(timer.nsecsElapsed()) * 1e-6;
        state.SetIterationTime((openMs + replotMs + closeMs) * 1e-3);
    }
    state.counters["open_ms"] = openMs;
    state.counters["replot_ms"] = replotMs;
    state.counters["close_ms"] = closeMs;
}
BENCHMARK(BM_ManySegments)
    ->Arg(1'000)
    ->Arg(10'000)
    ->Arg(100'000)
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

/// Counts the paint events of the widgets it watches.
class PaintCounter : public QObject {
public:
    int count = 0;
    bool eventFilter(QObject* watched, QEvent* event) override {
        if (event->type() == QEvent::Paint) ++count;
        return QObject::eventFilter(watched, event);
    }
};

void BM_CursorMove(benchmark::State& state) {
    auto window = makeWindow();
    QCustomPlot* velocity = window->plots()->plot(0);
    std::vector<QWidget*> painted = {window->plots()->plot(0), window->plots()->plot(1),
                                     window->plots()->plot(2), window->contourView()};
    std::vector<PaintCounter> counters(painted.size());
    for (std::size_t i = 0; i < painted.size(); ++i) painted[i]->installEventFilter(&counters[i]);
    const QRect rect = velocity->axisRect()->rect();
    int k = 0;
    for (auto _ : state) {
        std::vector<int> before;
        for (const PaintCounter& c : counters) before.push_back(c.count);
        // Sweep back and forth across the axis rect, a few pixels per move, as a hand would.
        const int span = rect.width() - 2;
        const int step = (k * 7) % (2 * span);
        const QPointF pos(rect.left() + 1 + (step < span ? step : 2 * span - step),
                          rect.center().y());
        ++k;
        QElapsedTimer timer;
        timer.start();
        QMouseEvent move(QEvent::MouseMove, pos, velocity->mapToGlobal(pos), Qt::NoButton,
                         Qt::NoButton, Qt::NoModifier);
        QCoreApplication::sendEvent(velocity, &move);
        auto allPainted = [&] {
            for (std::size_t i = 0; i < counters.size(); ++i) {
                if (counters[i].count == before[i]) return false;
            }
            return true;
        };
        while (!allPainted() && timer.elapsed() < 2000) {
            QCoreApplication::processEvents(QEventLoop::AllEvents);
        }
        state.SetIterationTime(static_cast<double>(timer.nsecsElapsed()) * 1e-9);
    }
    for (std::size_t i = 0; i < painted.size(); ++i) painted[i]->removeEventFilter(&counters[i]);
}
// 300 moves, each timed alone.
BENCHMARK(BM_CursorMove)
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1)
    ->Repetitions(300)
    ->ReportAggregatesOnly(true);

}  // namespace

int main(int argc, char** argv) {
    cam::keepFreedMemoryForReuse();  // as the app does
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);
    QApplication::setApplicationName("camwright-bench");
    benchmark::Initialize(&argc, argv);
    benchmark::RunSpecifiedBenchmarks();
    keptWindows.clear();
    benchmark::Shutdown();
    return 0;
}
