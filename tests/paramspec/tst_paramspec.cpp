// SPDX-License-Identifier: MIT
// Parameter specs: each kind accepts what its loaders accept and refuses the rest with the
// one wording every loader uses.
#include "paramspec.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QTest>

using namespace semhap;

Q_DECLARE_METATYPE(semhap::ParamSpec)

class TestParamSpec : public QObject
{
    Q_OBJECT

private slots:
    void check_data();
    void check();
    void missing_data();
    void missing();
    void defaults();
};

namespace {

QJsonValue json(const char *text)
{
    // Wrapped in an array, so scalars parse too.
    return QJsonDocument::fromJson(QByteArray("[") + text + "]").array().at(0);
}

ParamSpec grippers()
{
    return ParamSpec::choice("gripper", {"left", "right"}, QString(), "help");
}

} // namespace

void TestParamSpec::check_data()
{
    QTest::addColumn<ParamSpec>("spec");
    QTest::addColumn<QString>("value");
    QTest::addColumn<QString>("reason"); // empty: accepted

    const ParamSpec any = ParamSpec::number("x", 0, "N", "help");
    QTest::newRow("number") << any << "-3.5"
                            << "";
    QTest::newRow("number as text") << any << "\"3\""
                                    << "must be a finite number, found a string";
    QTest::newRow("number as list") << any << "[3]"
                                    << "must be a finite number, found an array";
    const ParamSpec nonNegative = any.atLeast(0);
    QTest::newRow("at least 0") << nonNegative << "0"
                                << "";
    QTest::newRow("negative") << nonNegative << "-0.5"
                              << "must not be negative, got -0.5";
    const ParamSpec positive = any.above(0);
    QTest::newRow("positive") << positive << "1e-9"
                              << "";
    QTest::newRow("zero, not positive") << positive << "0"
                                        << "must be positive, got 0";
    QTest::newRow("at least 2") << any.atLeast(2) << "1"
                                << "must be at least 2, got 1";
    QTest::newRow("above 2") << any.above(2) << "2"
                             << "must be greater than 2, got 2";
    QTest::newRow("at most 1") << any.atMost(1) << "1.5"
                               << "must be at most 1, got 1.5";
    const ParamSpec unit = any.atLeast(0).atMost(1);
    QTest::newRow("unit") << unit << "1"
                          << "";
    QTest::newRow("unit above") << unit << "2"
                                << "must be within [0, 1], got 2";
    QTest::newRow("unit below") << unit << "-1"
                                << "must be within [0, 1], got -1";

    QTest::newRow("choice") << grippers() << "\"left\""
                            << "";
    QTest::newRow("bad choice") << grippers() << "\"middle\""
                                << "must be \"left\" or \"right\"";
    QTest::newRow("choice not text") << grippers() << "1"
                                     << "must be \"left\" or \"right\"";
    const ParamSpec three = ParamSpec::choice("m", {"a", "b", "c"}, "a", "help");
    QTest::newRow("three choices") << three << "\"d\""
                                   << "must be \"a\", \"b\" or \"c\"";

    const ParamSpec filter = ParamSpec::anyOf("m", {"a", "b"}, "help");
    QTest::newRow("filter one") << filter << "\"a\""
                                << "";
    QTest::newRow("filter list") << filter << "[\"a\", \"b\"]"
                                 << "";
    QTest::newRow("filter bad item") << filter << "[\"a\", \"z\"]"
                                     << "must be \"a\" or \"b\", or a list of them";
    QTest::newRow("filter empty list") << filter << "[]"
                                       << "must be \"a\" or \"b\", or a list of them";

    const ParamSpec points = ParamSpec::of("points", ParamKind::Points, ParamAbsent::Default, "h");
    const QString pointsReason = "must be a list of [x, y] points with x increasing";
    QTest::newRow("points") << points << "[[0, 0], [1, 1]]"
                            << "";
    QTest::newRow("points x equal") << points << "[[0, 0], [0, 1]]" << pointsReason;
    QTest::newRow("points triple") << points << "[[0, 0, 1]]" << pointsReason;
    QTest::newRow("points empty") << points << "[]" << pointsReason;

    const ParamSpec channels =
        ParamSpec::of("channels", ParamKind::Channels, ParamAbsent::Default, "h");
    const QString channelsReason = "must be a non-empty array of channel names";
    QTest::newRow("channels") << channels << "[\"b1\", \"b2\"]"
                              << "";
    QTest::newRow("channels empty name") << channels << "[\"b1\", \"\"]" << channelsReason;
    QTest::newRow("channels one name") << channels << "\"b1\"" << channelsReason;

    const ParamSpec pattern =
        ParamSpec::of("pattern", ParamKind::Pattern, ParamAbsent::Required, "h");
    QTest::newRow("pattern") << pattern << "\"air.squeeze\""
                             << "";
    QTest::newRow("pattern empty") << pattern << "\"\""
                                   << "must be a pattern name or file";
    QTest::newRow("model number") << ParamSpec::of("model", ParamKind::Model,
                                                   ParamAbsent::Required, "h")
                                  << "3"
                                  << "must be a device model name or file";

    const ParamSpec start = ParamSpec::of("from", ParamKind::Start, ParamAbsent::Default, "h");
    QTest::newRow("start peak") << start << "\"peak\""
                                << "";
    QTest::newRow("start number") << start << "0.5"
                                  << "";
    QTest::newRow("start other") << start << "\"top\""
                                 << "must be \"current\", \"peak\" or a number";
}

void TestParamSpec::check()
{
    QFETCH(ParamSpec, spec);
    QFETCH(QString, value);
    QFETCH(QString, reason);
    QString why;
    QCOMPARE(spec.check(json(value.toUtf8().constData()), &why), reason.isEmpty());
    QCOMPARE(why, reason);
}

void TestParamSpec::missing_data()
{
    QTest::addColumn<ParamSpec>("spec");
    QTest::addColumn<QString>("reason");
    QTest::newRow("choice") << grippers() << "needs \"gripper\": \"left\" or \"right\"";
    QTest::newRow("number") << ParamSpec::number("level", 0, "", "h").required()
                            << "needs \"level\": a finite number";
    QTest::newRow("pattern") << ParamSpec::of("pattern", ParamKind::Pattern, ParamAbsent::Required,
                                              "h")
                             << "needs \"pattern\": a pattern name or file";
}

void TestParamSpec::missing()
{
    QFETCH(ParamSpec, spec);
    QFETCH(QString, reason);
    QCOMPARE(spec.absent, ParamAbsent::Required);
    QCOMPARE(spec.missingReason(), reason);
}

void TestParamSpec::defaults()
{
    QCOMPARE(ParamSpec::number("tau", 0.05, "s", "h").defaultValue(), QJsonValue(0.05));
    QCOMPARE(ParamSpec::choice("mode", {"block", "open"}, "block", "h").defaultValue(),
             QJsonValue("block"));
    QVERIFY(grippers().defaultValue().isUndefined());
    QVERIFY(ParamSpec::number("h", 0, "s", "h").computed().defaultValue().isUndefined());
    QVERIFY(ParamSpec::anyOf("m", {"a"}, "h").defaultValue().isUndefined());
    QCOMPARE(ParamSpec::anyOf("m", {"a"}, "h").absent, ParamAbsent::Any);

    const std::vector<ParamSpec> specs{grippers(), ParamSpec::number("x", 1, "", "h")};
    QCOMPARE(findParamSpec(specs, "x"), &specs[1]);
    QVERIFY(!findParamSpec(specs, "y"));
    QCOMPARE(paramSpecNames(specs), QStringList({"gripper", "x"}));
}

QTEST_GUILESS_MAIN(TestParamSpec)
#include "tst_paramspec.moc"
