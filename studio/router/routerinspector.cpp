// SPDX-License-Identifier: MIT
#include "routerinspector.h"

#include "paramform.h"
#include "patternlibrary.h"
#include "routereditor.h"
#include "routerscene.h"
#include "userpatterns.h"

#include <QLabel>
#include <QLineEdit>
#include <QScrollArea>
#include <QScrollBar>
#include <QTimer>
#include <QVBoxLayout>

#include <algorithm>

namespace semhap {

RouterInspector::RouterInspector(RouterEditor &editor, QWidget *parent)
    : QWidget(parent), m_editor(editor)
{
    setObjectName(QStringLiteral("routerInspector"));
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    auto *scroll = new QScrollArea(this);
    scroll->setObjectName(QStringLiteral("inspectorScroll"));
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    layout->addWidget(scroll);
}

void RouterInspector::forget()
{
    m_inspected.clear();
    schedule();
}

void RouterInspector::refresh()
{
    m_inspectedNode = RouterNode();
    schedule();
}

void RouterInspector::schedule()
{
    if (m_pending)
        return;
    m_pending = true;
    // Later: the field that made the edit may still be inside its signal.
    QTimer::singleShot(0, this, [this] {
        m_pending = false;
        rebuild();
    });
}

void RouterInspector::rebuild()
{
    const QStringList ids = m_editor.scene()->selectedNodeIds();
    const int index = ids.size() == 1 ? m_editor.graph().nodeIndex(ids.front()) : -1;
    auto *scroll = findChild<QScrollArea *>(QStringLiteral("inspectorScroll"));
    // The same node edited: the new fields show where the old ones were scrolled to, with
    // the focus in the field it was in (an edit jumped back to the top).
    int keptScroll = 0;
    ParamForm::Focus keptFocus;
    if (index >= 0 && m_inspected == m_editor.graph().nodes[size_t(index)].id &&
        scroll->widget()) {
        keptScroll = scroll->verticalScrollBar()->value();
        keptFocus = static_cast<ParamForm *>(scroll->widget())->focus();
    }
    if (index >= 0) {
        const RouterNode &node = m_editor.graph().nodes[size_t(index)];
        // Unchanged: keep the fields, and the focus the user is typing in.
        if (scroll->widget() && m_inspected == node.id && m_inspectedNode.type == node.type &&
            m_inspectedNode.params == node.params)
            return;
        m_inspected = node.id;
        m_inspectedNode = node;
    } else {
        m_inspected.clear();
    }

    auto *page = new ParamForm(ParamForm::Numbers::Typed);
    if (index < 0) {
        auto *hint =
            new QLabel(ids.isEmpty() ? tr("Select a node to edit its parameters.")
                                     : tr("%n nodes selected.", nullptr, int(ids.size())));
        hint->setWordWrap(true);
        page->addRow(hint);
        scroll->setWidget(page);
        return;
    }
    const RouterNode &node = m_editor.graph().nodes[size_t(index)];
    const RouterNodeType *type = routerNodeType(node.type);
    auto *title = new QLabel(
        type ? QStringLiteral("<b>%1</b> — %2").arg(node.type, type->description) : node.type);
    title->setWordWrap(true);
    page->addRow(title);
    auto *idEdit = new QLineEdit(node.id);
    idEdit->setObjectName(QStringLiteral("nodeId"));
    idEdit->setToolTip(tr("The name events and devices carry"));
    const QString id = node.id;
    connect(idEdit, &QLineEdit::editingFinished, this, [this, idEdit, id] {
        QString reason;
        if (!m_editor.renameNode(id, idEdit->text().trimmed(), &reason)) {
            emit status(reason, true);
            idEdit->setText(id);
        }
    });
    page->addRow(tr("id"), idEdit);

    offerChoices(*page, node);
    connect(page, &ParamForm::edited, this,
            [this, id](const QString &key, const QJsonValue &value) {
                m_editor.setParam(id, key, value);
            });
    const std::vector<ParamSpec> specs = m_editor.graph().paramsOf(node);
    for (const ParamSpec &spec : specs)
        page->addParam(spec, node.params.value(spec.name), spec.name);
    for (auto it = node.params.begin(); it != node.params.end(); ++it) {
        if (!findParamSpec(specs, it.key()))
            page->addUnknown(it.key(), it.value()); // shown so it can be cleared
    }
    scroll->setWidget(page);
    if (keptScroll > 0) {
        page->adjustSize(); // the scroll range follows the new page at once
        scroll->verticalScrollBar()->setValue(keptScroll);
    }
    page->restoreFocus(keptFocus);
}

void RouterInspector::offerChoices(ParamForm &form, const RouterNode &node) const
{
    const auto names = [](const QStringList &list) {
        QList<ParamForm::Choice> choices;
        for (const QString &name : list)
            choices.append({name, name});
        return choices;
    };
    // What the source's frames carry for the node's gripper (both grippers' while it has none).
    const QString hand = node.params.value(QStringLiteral("gripper")).toString();
    form.setChoices(ParamKind::Signal, [this, names, hand] {
        QStringList signalNames;
        const RouterContext source = m_editor.context();
        for (Gripper gripper : {Gripper::Left, Gripper::Right}) {
            if (hand.isEmpty() || hand == gripperName(gripper))
                signalNames.append(source.signalNames[size_t(gripper)]);
        }
        return names(signalNames);
    });
    // The new messages other nodes of the graph name.
    const ParamForm::Choices messages = [this, names] {
        return names(m_editor.newMessageNames());
    };
    form.setChoices(ParamKind::Choice, messages);
    form.setChoices(ParamKind::Choices, messages);
    form.setChoices(ParamKind::Pattern, [this, names] {
        QStringList builtin;
        for (const PatternPtr &pattern : m_editor.graph().patterns)
            builtin.append(pattern->name());
        QList<ParamForm::Choice> choices = names(builtin + PatternLibrary::builtinNames());
        // The designer's saved patterns, by name; the node names the file, which the router
        // loads (and a self-contained save embeds).
        for (const UserPattern &pattern : userPatterns()) {
            const bool taken = std::any_of(choices.begin(), choices.end(),
                                           [&](const auto &c) { return c.text == pattern.name; });
            choices.append(
                {taken ? tr("%1 (your file)").arg(pattern.name) : pattern.name, pattern.path});
        }
        return choices;
    });
    form.setChoices(ParamKind::Model, [this, names] {
        QStringList models;
        for (const DeviceModelPtr &model : m_editor.graph().models)
            models.append(model->name());
        return names(models + DeviceModelLibrary::builtinNames());
    });
}

} // namespace semhap
