// SPDX-License-Identifier: MIT
#pragma once

#include "studio.h"

#include <QSize>
#include <QString>
#include <QTest>
#include <QWidget>

/** The window sizes and languages a picture of a new piece of the window is taken at. */
inline void addWindowRows()
{
    QTest::addColumn<QSize>("size");
    QTest::addColumn<QString>("language");
    QTest::newRow("1280x800") << QSize(1280, 800) << "en";
    QTest::newRow("1920x1080") << QSize(1920, 1080) << "en";
    QTest::newRow("1280x800-de") << QSize(1280, 800) << "de";
}

/** Saves `widget` as NAME-ROW.png in $SEMHAP_SCREENSHOTS, to be looked at, if it is set. */
inline void savePicture(QWidget *widget, const QString &name)
{
    const QString folder = qEnvironmentVariable("SEMHAP_SCREENSHOTS");
    QString error;
    if (!folder.isEmpty() &&
        !semhap::Studio::screenshot(
            widget, QString("%1/%2-%3.png").arg(folder, name, QTest::currentDataTag()), &error))
        qWarning("%s", qPrintable(error));
}
