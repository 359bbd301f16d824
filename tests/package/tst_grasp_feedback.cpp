// SPDX-License-Identifier: MIT
// A user's own test of a feedback design: feed contact frames to the C3 router and assert on
// the semantic events and on what the wristbands are told.
#include <semhap/pipeline.h>

#include <QJsonDocument>
#include <QJsonObject>
#include <QTest>

#include <vector>

namespace {

/** Keeps everything the pipeline produces. */
class Collect : public semhap::PipelineSink
{
public:
    void onEvent(const semhap::SemanticEvent &e) override { events.push_back(e); }
    void onDeviceFrame(const semhap::DeviceFrame &f) override { frames.push_back(f); }
    std::vector<semhap::SemanticEvent> events;
    std::vector<semhap::DeviceFrame> frames;
};

/** The right gripper pinching one cube with total force F, split over both fingertips. */
semhap::ContactFrame pinch(double t, double force)
{
    semhap::ContactFrame frame;
    frame.t = t;
    frame.gripper = semhap::Gripper::Right;
    frame.left = {force / 2, 16, 0, false, {}};
    frame.right = {force / 2, 16, 0, false, {}};
    return frame;
}

} // namespace

class TestGraspFeedback : public QObject
{
    Q_OBJECT

private slots:
    void squeezeTooHardWarns()
    {
        semhap::LoadError error;
        std::unique_ptr<semhap::Router> router = semhap::loadRouter("C3", {}, &error);
        QVERIFY2(router, qPrintable(error.toString()));
        semhap::Pipeline pipeline(std::move(router));
        Collect out;

        // 0 N, a firm grasp (40 N) from 0.1 s, then too hard (100 N) from 0.7 s.
        for (int k = 0; k <= 10; ++k) {
            pipeline.process(pinch(0.1 * k, k == 0 ? 0.0 : k < 7 ? 40.0 : 100.0), out);
            pipeline.flush(out);
        }

        QCOMPARE(out.events.size(), size_t(2));
        QCOMPARE(out.events[0].message, semhap::Message::Grasp);
        QCOMPARE(out.events[0].phase, semhap::EventPhase::Begin);
        QCOMPARE(out.events[1].message, semhap::Message::Break);
        QCOMPARE(out.events[1].intensity, 0.5); // (100 - 80) / (120 - 80)
        QCOMPARE(pipeline.router().nodeIds()[out.events[1].node], QString("right.force"));

        // The air band confirms the grasp: 0.9 s after it began it is fully inflated.
        const int air = pipeline.router().player().deviceIndex("right.air");
        QCOMPARE(pipeline.router().player().lastFrame(air).values[0], 1.0);
    }

    void aSignalOfYourTaskConfirms()
    {
        // A frame's named signal, a threshold with a message of its own: "aligned" while the
        // plug's angle error is under 0.03 rad.
        const QJsonObject json = QJsonDocument::fromJson(R"({"format": "semhap.router/1",
          "nodes": [
            {"id": "angle", "type": "signal",
             "params": {"gripper": "right", "quantity": "plug.angle"}},
            {"id": "aligned", "type": "threshold",
             "params": {"gripper": "right", "message": "aligned", "category": "confirmation",
                        "condition": "below", "begin": 0.03}}],
          "links": [{"from": "angle", "to": "aligned"}]})")
                                     .object();
        semhap::RouterGraph graph;
        semhap::LoadError error;
        QVERIFY2(semhap::RouterGraph::fromJson(json, "mine.json", &graph, &error),
                 qPrintable(error.toString()));
        std::unique_ptr<semhap::Router> router = semhap::Router::compile(graph, &error);
        QVERIFY2(router, qPrintable(error.toString()));
        semhap::Pipeline pipeline(std::move(router));
        Collect out;
        const int angle = semhap::signalNames().intern("plug.angle");
        for (int k = 0; k <= 4; ++k) {
            semhap::ContactFrame frame = pinch(0.1 * k, 0.0);
            frame.signalValues.set(angle, 0.1 - 0.025 * k); // 0.1 rad down to 0
            pipeline.process(frame, out);
            pipeline.flush(out);
        }
        QCOMPARE(out.events.size(), size_t(1));
        QCOMPARE(semhap::messageName(out.events[0].message), QString("aligned"));
        QCOMPARE(out.events[0].category, semhap::Category::Confirmation);
        QCOMPARE(out.events[0].t, 0.3); // 0.025 rad: the first below 0.03
    }
};

QTEST_GUILESS_MAIN(TestGraspFeedback)
#include "tst_grasp_feedback.moc"
