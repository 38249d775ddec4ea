// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QString>
#include <QStringList>

namespace ui {

/**
 * The "Open Recent" list, most recent first, kept in QSettings under one key. Files that no
 * longer exist are dropped whenever the list is read.
 */
class RecentFiles {
public:
    static constexpr int kMaxEntries = 10;

    explicit RecentFiles(QString settingsKey = QStringLiteral("recentFiles"));

    /** The existing files, most recent first; missing ones are removed from the settings too. */
    QStringList files() const;
    /** Moves path (made absolute) to the front, trimming the list to kMaxEntries. */
    void add(const QString& path) const;
    void remove(const QString& path) const;
    void clear() const;

private:
    QStringList stored() const;
    void store(const QStringList& files) const;

    QString m_key;
};

} // namespace ui
