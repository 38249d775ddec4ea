// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/shell/source_names.h"

#include <QCoreApplication>
#include <QFileInfo>
#include <QLocale>

#include "core/model/builtin_models.h"

namespace ui {

namespace {
const QString kBuiltinPrefix = QString::fromLatin1(core::kBuiltinPrefix);
} // namespace

bool isBuiltinSource(const QString& source) {
    return source.startsWith(kBuiltinPrefix);
}

// The labels keep the main window's translation context, where the menu shows them.
QString builtinLabel(const QString& name) {
    if (name == QLatin1String("trefoil"))
        return QCoreApplication::translate("ui::MainWindow", "Trefoil knot");
    if (name == QLatin1String("hexring"))
        return QCoreApplication::translate("ui::MainWindow", "Hexagonal ring");
    if (name == QLatin1String("row"))
        return QCoreApplication::translate("ui::MainWindow", "Row of four");
    if (name == QLatin1String("knot"))
        return QCoreApplication::translate("ui::MainWindow", "Torus knot (1M triangles)");
    if (name.startsWith(QLatin1String("knot?triangles=")))
        return QCoreApplication::translate("ui::MainWindow", "Torus knot (%1 triangles)")
            .arg(QLocale().toString(name.mid(15).toLongLong()));
    // A model added to core before the GUI learnt its label: its English description.
    for (const core::BuiltinModel& model : core::builtinModels()) {
        if (QString::fromStdString(model.name) == name)
            return QString::fromStdString(model.description);
    }
    return name;
}

QString sourceDisplayName(const QString& source) {
    if (isBuiltinSource(source))
        return builtinLabel(source.mid(kBuiltinPrefix.size()));
    return QFileInfo(source).fileName();
}

} // namespace ui
