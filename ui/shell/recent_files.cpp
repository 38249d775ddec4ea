// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/shell/recent_files.h"

#include <QFileInfo>
#include <QSettings>

#include <utility>

namespace ui {

namespace {
QString normalized(const QString& path) {
    const QFileInfo info(path);
    const QString canonical = info.canonicalFilePath();
    return canonical.isEmpty() ? info.absoluteFilePath() : canonical;
}
} // namespace

RecentFiles::RecentFiles(QString settingsKey) : m_key(std::move(settingsKey)) {}

QStringList RecentFiles::files() const {
    const QStringList all = stored();
    QStringList existing;
    for (const QString& path : all) {
        if (QFileInfo(path).isFile())
            existing.append(path);
    }
    if (existing.size() != all.size())
        store(existing);
    return existing;
}

void RecentFiles::add(const QString& path) const {
    const QString entry = normalized(path);
    QStringList list = stored();
    list.removeAll(entry);
    list.prepend(entry);
    while (list.size() > kMaxEntries)
        list.removeLast();
    store(list);
}

void RecentFiles::remove(const QString& path) const {
    QStringList list = stored();
    list.removeAll(path);
    list.removeAll(normalized(path));
    store(list);
}

void RecentFiles::clear() const {
    store({});
}

QStringList RecentFiles::stored() const {
    return QSettings().value(m_key).toStringList();
}

void RecentFiles::store(const QStringList& files) const {
    QSettings().setValue(m_key, files);
}

} // namespace ui
