// SPDX-License-Identifier: MIT
// The form both inspectors build from parameter specs: which field each kind gets, how typed
// text becomes JSON in English and German, what an absent value shows, and the keyboard
// kept across a rebuild.
#include "numberedit.h"
#include "paramform.h"

#include <QApplication>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QJsonArray>
#include <QJsonDocument>
#include <QLabel>
#include <QLineEdit>
#include <QSignalSpy>
#include <QTest>

using namespace semhap;

namespace {

/** The specs the rows name, one of each kind a form types into. */
ParamSpec specNamed(const QString &name)
{
    if (name == QLatin1String("number"))
        return ParamSpec::number(name, 20, QStringLiteral("N"), QStringLiteral("A force"));
    if (name == QLatin1String("level"))
        return ParamSpec::of(name, ParamKind::Level, ParamAbsent::Required,
                             QStringLiteral("A level"));
    if (name == QLatin1String("points"))
        return ParamSpec::of(name, ParamKind::Points, ParamAbsent::Default,
                             QStringLiteral("Points"));
    if (name == QLatin1String("channels"))
        return ParamSpec::of(name, ParamKind::Channels, ParamAbsent::Default,
                             QStringLiteral("Channels"));
    if (name == QLatin1String("signal"))
        return ParamSpec::of(name, ParamKind::Signal, ParamAbsent::Required,
                             QStringLiteral("A signal"))
            .withChoices({QStringLiteral("force")});
    if (name == QLatin1String("messages"))
        return ParamSpec::anyOf(name, {QStringLiteral("grasp"), QStringLiteral("break")},
                                QStringLiteral("Messages"))
            .orNewName();
    return ParamSpec::of(name, ParamKind::Pattern, ParamAbsent::Required,
                         QStringLiteral("A file"));
}

QByteArray json(const QJsonValue &value)
{
    if (value.isUndefined())
        return "undefined";
    return QJsonDocument(QJsonArray{value}).toJson(QJsonDocument::Compact);
}

/** Types into a field as a user does: everything selected, the text, Return. */
void type(QWidget *field, const QString &text)
{
    auto *combo = qobject_cast<QComboBox *>(field);
    QWidget *target = combo ? combo->lineEdit() : field;
    target->setFocus();
    QTest::keyClick(target, Qt::Key_A, Qt::ControlModifier);
    QTest::keyClicks(target, text);
    QTest::keyClick(target, Qt::Key_Return);
}

} // namespace

class TestParamForm : public QObject
{
    Q_OBJECT

private slots:
    void cleanup() { QLocale::setDefault(QLocale::c()); }
    void typedTextBecomesJson_data();
    void typedTextBecomesJson();
    void showsValuesInTheUsersLocale_data();
    void showsValuesInTheUsersLocale();
    void textNotUnderstoodChangesNothing();
    void choicesOfferWhatLeavesThemOut();
    void nameFieldsAskTheirOwnerEachTimeTheyOpen();
    void boundNumbersAndStartsAreSpinBoxes();
    void keepsTheKeyboardAcrossARebuild();
};

void TestParamForm::typedTextBecomesJson_data()
{
    QTest::addColumn<QString>("locale");
    QTest::addColumn<QString>("param");
    QTest::addColumn<QString>("typed");
    QTest::addColumn<QByteArray>("value");

    QTest::newRow("number") << "en"
                            << "number"
                            << "12.5" << QByteArray("[12.5]");
    QTest::newRow("number de") << "de"
                               << "number"
                               << "12,5" << QByteArray("[12.5]");
    QTest::newRow("number not a number") << "en"
                                         << "number"
                                         << "ten" << QByteArray("[\"ten\"]");
    QTest::newRow("level") << "en"
                           << "level"
                           << "80" << QByteArray("[80]");
    QTest::newRow("level json") << "en"
                                << "level"
                                << "[0.02, 0.08]" << QByteArray("[[0.02,0.08]]");
    QTest::newRow("level bare") << "en"
                                << "level"
                                << "0.02, 0.08" << QByteArray("[[0.02,0.08]]");
    QTest::newRow("level de") << "de"
                              << "level"
                              << "0,02; 0,08" << QByteArray("[[0.02,0.08]]");
    QTest::newRow("level de commas") << "de"
                                     << "level"
                                     << "0,02, 0,08" << QByteArray("[[0.02,0.08]]");
    QTest::newRow("points") << "en"
                            << "points"
                            << "0:0, 0.5:1" << QByteArray("[[[0,0],[0.5,1]]]");
    QTest::newRow("points tight") << "en"
                                  << "points"
                                  << "0:0,0.5:1" << QByteArray("[[[0,0],[0.5,1]]]");
    QTest::newRow("points de") << "de"
                               << "points"
                               << "0:0; 0,5:1" << QByteArray("[[[0,0],[0.5,1]]]");
    QTest::newRow("points json") << "de"
                                 << "points"
                                 << "[[0, 0], [1, 2]]" << QByteArray("[[[0,0],[1,2]]]");
    QTest::newRow("channels") << "en"
                              << "channels"
                              << "p0, p1" << QByteArray("[[\"p0\",\"p1\"]]");
    QTest::newRow("one channel") << "en"
                                 << "channels"
                                 << "p0" << QByteArray("[[\"p0\"]]");
    QTest::newRow("numeric signal") << "en"
                                    << "signal"
                                    << "12" << QByteArray("[\"12\"]");
    QTest::newRow("new messages") << "en"
                                  << "messages"
                                  << "grasp, aligned" << QByteArray("[[\"grasp\",\"aligned\"]]");
    QTest::newRow("one new message") << "en"
                                     << "messages"
                                     << "aligned" << QByteArray("[\"aligned\"]");
    QTest::newRow("pattern file") << "en"
                                  << "pattern"
                                  << " my.json " << QByteArray("[\"my.json\"]");
}

void TestParamForm::typedTextBecomesJson()
{
    QFETCH(QString, locale);
    QFETCH(QString, param);
    QFETCH(QString, typed);
    QFETCH(QByteArray, value);
    QLocale::setDefault(QLocale(locale));
    ParamForm form(ParamForm::Numbers::Typed);
    form.addParam(specNamed(param), QJsonValue(QJsonValue::Undefined), param);
    form.show();
    QVERIFY(QTest::qWaitForWindowExposed(&form));
    QSignalSpy edited(&form, &ParamForm::edited);
    auto *field = form.findChild<QWidget *>(ParamForm::fieldName(param));
    QVERIFY(field);
    type(field, typed);
    QVERIFY(!edited.isEmpty());
    QCOMPARE(edited.last().at(0).toString(), param);
    QCOMPARE(json(edited.last().at(1).toJsonValue()), value);
}

void TestParamForm::showsValuesInTheUsersLocale_data()
{
    QTest::addColumn<QString>("locale");
    QTest::addColumn<QString>("param");
    QTest::addColumn<QByteArray>("value");
    QTest::addColumn<QString>("shown");

    QTest::newRow("number") << "en"
                            << "number" << QByteArray("[0.25]") << "0.25";
    QTest::newRow("number de") << "de"
                               << "number" << QByteArray("[0.25]") << "0,25";
    QTest::newRow("absent") << "de"
                            << "number" << QByteArray("[]") << "";
    QTest::newRow("range") << "en"
                           << "level" << QByteArray("[[0.02,0.08]]") << "[0.02, 0.08]";
    QTest::newRow("range de") << "de"
                              << "level" << QByteArray("[[0.02,0.08]]") << "[0,02; 0,08]";
    QTest::newRow("points") << "en"
                            << "points" << QByteArray("[[[0,0],[0.5,1]]]") << "0:0, 0.5:1";
    QTest::newRow("points de") << "de"
                               << "points" << QByteArray("[[[0,0],[0.5,1]]]") << "0:0; 0,5:1";
    QTest::newRow("channels") << "en"
                              << "channels" << QByteArray("[[\"p0\",\"p1\"]]") << "p0, p1";
}

void TestParamForm::showsValuesInTheUsersLocale()
{
    QFETCH(QString, locale);
    QFETCH(QString, param);
    QFETCH(QByteArray, value);
    QFETCH(QString, shown);
    QLocale::setDefault(QLocale(locale));
    const QJsonArray wrapped = QJsonDocument::fromJson(value).array();
    ParamForm form(ParamForm::Numbers::Typed);
    form.addParam(specNamed(param), wrapped.isEmpty() ? QJsonValue() : wrapped.at(0), param);
    auto *line = form.findChild<QLineEdit *>(ParamForm::fieldName(param));
    QVERIFY(line);
    QCOMPARE(line->text(), shown);
    if (shown.isEmpty())
        QCOMPARE(line->placeholderText(), ParamForm::tr("(default: %1)").arg("20"));
}

void TestParamForm::textNotUnderstoodChangesNothing()
{
    ParamForm form(ParamForm::Numbers::Typed);
    form.addParam(specNamed("points"), QJsonValue(), "points");
    form.show();
    QVERIFY(QTest::qWaitForWindowExposed(&form));
    QSignalSpy edited(&form, &ParamForm::edited);
    auto *line = form.findChild<QLineEdit *>(ParamForm::fieldName("points"));
    type(line, "0:0, half:1");
    QVERIFY(edited.isEmpty());
    QCOMPARE(line->toolTip(), ParamForm::tr("Not understood; nothing was changed"));
    QVERIFY(line->styleSheet().contains("border"));
}

void TestParamForm::choicesOfferWhatLeavesThemOut()
{
    // A choice that may be left out starts with the entry that leaves it out; a required
    // one without a value shows what is missing and offers only real choices.
    ParamForm form(ParamForm::Numbers::Typed);
    form.addParam(ParamSpec::choice("gripper", {"left", "right"}, "left", "The hand"),
                  QJsonValue(), "gripper");
    form.addParam(ParamSpec::choice("mode", {"open", "closed"}, QString(), "The mode"),
                  QJsonValue(), "mode");
    form.addParam(ParamSpec::anyOf("message", {"grasp", "break"}, "Which messages"),
                  QJsonValue("break"), "message");
    auto *gripper = form.findChild<QComboBox *>(ParamForm::fieldName("gripper"));
    auto *mode = form.findChild<QComboBox *>(ParamForm::fieldName("mode"));
    auto *message = form.findChild<QComboBox *>(ParamForm::fieldName("message"));
    QVERIFY(gripper && mode && message);
    QCOMPARE(gripper->count(), 3);
    QCOMPARE(gripper->currentText(), ParamForm::tr("(default: %1)").arg("left"));
    QCOMPARE(mode->count(), 2);
    QCOMPARE(mode->currentIndex(), -1);
    QCOMPARE(mode->placeholderText(), ParamForm::tr("(none)"));
    QCOMPARE(message->currentText(), QString("break"));

    QSignalSpy edited(&form, &ParamForm::edited);
    emit message->activated(0);
    QCOMPARE(json(edited.last().at(1).toJsonValue()), QByteArray("undefined"));
    emit gripper->activated(2);
    QCOMPARE(json(edited.last().at(1).toJsonValue()), QByteArray("[\"right\"]"));
    QCOMPARE(form.findChild<QLabel *>()->toolTip(), QString("The hand"));
}

void TestParamForm::nameFieldsAskTheirOwnerEachTimeTheyOpen()
{
    ParamForm form(ParamForm::Numbers::Typed);
    QStringList live{"plug.force"};
    form.setChoices(ParamKind::Signal, [&live] {
        QList<ParamForm::Choice> choices;
        for (const QString &name : live)
            choices.append({name, name});
        return choices;
    });
    form.setChoices(ParamKind::Pattern, [] {
        return QList<ParamForm::Choice>{{"air.squeeze", "air.squeeze"},
                                        {"mine", "/home/user/patterns/mine.json"}};
    });
    form.addParam(specNamed("signal"), QJsonValue(), "signal");
    form.addParam(specNamed("pattern"), QJsonValue("/home/user/patterns/mine.json"), "pattern");
    form.show();
    QVERIFY(QTest::qWaitForWindowExposed(&form));
    auto *signal = form.findChild<QComboBox *>(ParamForm::fieldName("signal"));
    QCOMPARE(signal->count(), 2); // the spec's, then the owner's
    live.append("plug.angle");    // the source's frames carry a new signal
    signal->showPopup();
    QCOMPARE(signal->count(), 3);
    QCOMPARE(signal->itemText(2), QString("plug.angle"));
    signal->hidePopup();

    // A file is shown by its name and set by its path.
    auto *pattern = form.findChild<QComboBox *>(ParamForm::fieldName("pattern"));
    QCOMPARE(pattern->currentText(), QString("mine"));
    QSignalSpy edited(&form, &ParamForm::edited);
    type(pattern, "mine");
    QCOMPARE(json(edited.last().at(1).toJsonValue()),
             QByteArray("[\"/home/user/patterns/mine.json\"]"));
}

void TestParamForm::boundNumbersAndStartsAreSpinBoxes()
{
    ParamForm form(ParamForm::Numbers::Bound);
    form.setBindings({"intensity"});
    form.addParam(ParamSpec::number("freq", 5, "Hz", "Its frequency").atLeast(0), QJsonValue(),
                  "Frequency");
    const ParamSpec from = ParamSpec::of("from", ParamKind::Start, ParamAbsent::Default, "Start");
    form.addParam(from, QJsonValue(0.3), "Starts from");
    form.addParam(ParamSpec::of("of", ParamKind::Waveforms, ParamAbsent::Required, "Inputs"),
                  QJsonValue(), "Inputs");
    auto *freq = form.findChild<NumberEdit *>(ParamForm::fieldName("freq"));
    QVERIFY(freq);
    QCOMPARE(freq->number(), QJsonValue(5.0)); // absent: its default
    QCOMPARE(qobject_cast<QLabel *>(
                 form.findChildren<QLabel *>(QString(), Qt::FindDirectChildrenOnly).at(0))
                 ->text(),
             ParamForm::tr("%1 (%2)").arg("Frequency", "Hz"));
    // A fixed start: the choice, then its value.
    auto *start = form.findChild<QComboBox *>(ParamForm::fieldName("from"));
    QCOMPARE(start->currentData().toString(), QString("value"));
    auto *startValue = form.findChild<NumberEdit *>(ParamForm::fieldName("from"));
    QVERIFY(startValue);
    QCOMPARE(startValue->number(), QJsonValue(0.3));
    QCOMPARE(form.findChildren<QLabel *>(QString(), Qt::FindDirectChildrenOnly).size(),
             3); // inputs have no field

    QSignalSpy edited(&form, &ParamForm::edited);
    emit start->activated(1);
    QCOMPARE(json(edited.last().at(1).toJsonValue()), QByteArray("[\"peak\"]"));
    auto *spin = freq->findChild<QDoubleSpinBox *>("value");
    spin->setFocus();
    spin->setValue(7);
    QCOMPARE(edited.last().at(0).toString(), QString("freq"));
    QCOMPARE(json(edited.last().at(1).toJsonValue()), QByteArray("[7]"));
}

void TestParamForm::keepsTheKeyboardAcrossARebuild()
{
    ParamForm form(ParamForm::Numbers::Bound);
    form.addParam(ParamSpec::number("amp", 1, "", "Its amplitude"), QJsonValue(), "Amplitude");
    form.addParam(ParamSpec::number("offset", 0, "", "Added"), QJsonValue(), "Offset");
    form.show();
    QVERIFY(QTest::qWaitForWindowExposed(&form));
    QApplication::setActiveWindow(&form);
    form.findChild<QWidget *>(ParamForm::fieldName("offset"))
        ->findChild<QDoubleSpinBox *>("value")
        ->setFocus();
    QTRY_VERIFY(QApplication::focusWidget());
    const ParamForm::Focus focus = form.focus();
    QCOMPARE(focus.field, ParamForm::fieldName("offset"));
    QCOMPARE(focus.part, QString("value"));
    form.clear();
    form.addParam(ParamSpec::number("amp", 1, "", "Its amplitude"), QJsonValue(), "Amplitude");
    form.addParam(ParamSpec::number("offset", 0, "", "Added"), QJsonValue(2.0), "Offset");
    form.restoreFocus(focus);
    QWidget *now = QApplication::focusWidget();
    QVERIFY(now);
    QCOMPARE(now->objectName(), QString("value"));
    QCOMPARE(now->parentWidget()->objectName(), ParamForm::fieldName("offset"));
}

QTEST_MAIN(TestParamForm)
#include "tst_paramform.moc"
