// SPDX-License-Identifier: GPL-3.0-or-later
// Every user-visible string has a finished translation in every language: lupdate runs over the
// GUI's sources (as the update_translations target does) into temporary copies of
// translations/*.ts, so a string added to the code and not yet translated fails here too. A
// translation must keep the source's placeholders (%1, %n) and, where the source has one, an
// accelerator (&).
#include <gtest/gtest.h>

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QProcess>
#include <QRegularExpression>
#include <QSet>
#include <QStringList>
#include <QTemporaryDir>
#include <QXmlStreamReader>

#include <string>
#include <vector>

namespace translations_test {

struct Message {
    QString context;
    QString source;
    bool numerus = false;
    QString type;             // of <translation>: "", "unfinished", "vanished", "obsolete"
    QStringList translations; // the text, or one per numerus form
};

/** The messages of a .ts file; error is set when it cannot be read. */
std::vector<Message> readTs(const QString& path, QString& language, QString& error) {
    std::vector<Message> messages;
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        error = path + QStringLiteral(": cannot be opened");
        return messages;
    }
    QXmlStreamReader xml(&file);
    QString context;
    while (!xml.atEnd()) {
        if (xml.readNext() != QXmlStreamReader::StartElement)
            continue;
        const auto name = xml.name();
        if (name == QLatin1String("TS")) {
            language = xml.attributes().value(QLatin1String("language")).toString();
        } else if (name == QLatin1String("name")) {
            context = xml.readElementText();
        } else if (name == QLatin1String("message")) {
            Message m;
            m.context = context;
            m.numerus = xml.attributes().value(QLatin1String("numerus")) == QLatin1String("yes");
            while (xml.readNextStartElement()) {
                if (xml.name() == QLatin1String("source")) {
                    m.source = xml.readElementText();
                } else if (xml.name() == QLatin1String("translation")) {
                    m.type = xml.attributes().value(QLatin1String("type")).toString();
                    if (m.numerus) {
                        while (xml.readNextStartElement()) {
                            if (xml.name() == QLatin1String("numerusform"))
                                m.translations.append(xml.readElementText());
                            else
                                xml.skipCurrentElement();
                        }
                    } else {
                        m.translations.append(xml.readElementText());
                    }
                } else {
                    xml.skipCurrentElement();
                }
            }
            messages.push_back(m);
        }
    }
    if (xml.hasError())
        error = QStringLiteral("%1:%2: %3").arg(path).arg(xml.lineNumber()).arg(xml.errorString());
    return messages;
}

/** The placeholders of a text: %1 … %99 (also %L1) and %n, as a sorted set. */
QSet<QString> placeholders(const QString& text) {
    static const QRegularExpression re(QStringLiteral("%L?(\\d{1,2}|n)"));
    QSet<QString> found;
    for (const QRegularExpressionMatch& m : re.globalMatch(text))
        found.insert(m.captured(1));
    return found;
}

/** Whether a text has a keyboard accelerator: an & not doubled. */
bool hasAccelerator(QString text) {
    text.remove(QStringLiteral("&&"));
    const int at = int(text.indexOf(QLatin1Char('&')));
    return at >= 0 && at + 1 < text.size() && !text.at(at + 1).isSpace();
}

/** What is wrong with m's translation, or an empty string. */
QString problem(const Message& m) {
    if (m.type == QLatin1String("unfinished"))
        return QStringLiteral("unfinished");
    if (m.type == QLatin1String("vanished") || m.type == QLatin1String("obsolete"))
        return QStringLiteral("%1 (the source no longer has it: update the .ts)").arg(m.type);
    if (m.translations.isEmpty())
        return QStringLiteral("no translation");
    const QSet<QString> wanted = placeholders(m.source);
    for (const QString& t : m.translations) {
        if (t.trimmed().isEmpty())
            return QStringLiteral("an empty translation");
        QSet<QString> got = placeholders(t);
        // A singular form may spell "one" out instead of %n.
        if (m.numerus && m.translations.size() > 1 && &t == &m.translations.first())
            got.insert(QStringLiteral("n"));
        if (got != wanted)
            return QStringLiteral("placeholders differ in \"%1\"").arg(t);
        if (hasAccelerator(m.source) && !hasAccelerator(t))
            return QStringLiteral("no accelerator (&) in \"%1\"").arg(t);
    }
    return {};
}

QStringList split(const char* list) {
    return QString::fromUtf8(list).split(QLatin1Char('|'), Qt::SkipEmptyParts);
}

TEST(Translations, PlaceholderAndAcceleratorRules) {
    EXPECT_EQ(placeholders(QStringLiteral("%1 of %L2, %n (%%)")),
              (QSet<QString>{QStringLiteral("1"), QStringLiteral("2"), QStringLiteral("n")}));
    EXPECT_TRUE(placeholders(QStringLiteral("100 %")).isEmpty());
    EXPECT_TRUE(hasAccelerator(QStringLiteral("&File")));
    EXPECT_TRUE(hasAccelerator(QStringLiteral("文件(&F)")));
    EXPECT_FALSE(hasAccelerator(QStringLiteral("Fish && Chips")));
    Message m{QStringLiteral("c"), QStringLiteral("&Open %1"), false, QString(), {}};
    m.translations = {QStringLiteral("Ö&ffnen %1")};
    EXPECT_EQ(problem(m), QString());
    m.translations = {QStringLiteral("Öffnen %1")};
    EXPECT_NE(problem(m), QString());
    m.translations = {QStringLiteral("Ö&ffnen")};
    EXPECT_NE(problem(m), QString());
    m.type = QStringLiteral("unfinished");
    EXPECT_EQ(problem(m), QStringLiteral("unfinished"));
}

TEST(Translations, EverySourceStringHasAFinishedTranslationInEveryLanguage) {
    const QStringList tsFiles = split(LAYERPAINT_TS_FILES);
    ASSERT_GE(tsFiles.size(), 2) << "translations/*.ts not found";
    const QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    QStringList copies;
    for (const QString& ts : tsFiles) {
        const QString copy = dir.filePath(QFileInfo(ts).fileName());
        ASSERT_TRUE(QFile::copy(ts, copy)) << ts.toStdString();
        QFile::setPermissions(copy, QFile::ReadOwner | QFile::WriteOwner);
        copies.append(copy);
    }
    // The options of qt_add_translations in app/CMakeLists.txt.
    QProcess lupdate;
    QStringList arguments{QStringLiteral("-no-obsolete"),
                          QStringLiteral("-locations"),
                          QStringLiteral("none"),
                          QStringLiteral("-I"),
                          QStringLiteral(LAYERPAINT_SOURCE_DIR),
                          QStringLiteral("@") + QStringLiteral(LAYERPAINT_TRANSLATION_SOURCES),
                          QStringLiteral("-ts")};
    arguments += copies;
    lupdate.start(QStringLiteral(LAYERPAINT_LUPDATE), arguments);
    ASSERT_TRUE(lupdate.waitForFinished(120000)) << lupdate.errorString().toStdString();
    ASSERT_EQ(lupdate.exitCode(), 0) << lupdate.readAllStandardError().toStdString();

    QStringList problems;
    QSet<QString> languages;
    for (const QString& copy : copies) {
        QString language, error;
        const std::vector<Message> messages = readTs(copy, language, error);
        ASSERT_TRUE(error.isEmpty()) << error.toStdString();
        EXPECT_GT(messages.size(), 100u) << copy.toStdString() << ": too few messages";
        languages.insert(language);
        for (const Message& m : messages) {
            const QString what = problem(m);
            if (!what.isEmpty())
                problems.append(QStringLiteral("%1: %2: \"%3\": %4")
                                    .arg(QFileInfo(copy).fileName(), m.context, m.source, what));
        }
    }
    EXPECT_TRUE(languages.contains(QStringLiteral("de")));
    EXPECT_TRUE(languages.contains(QStringLiteral("zh_CN")));
    EXPECT_TRUE(problems.isEmpty())
        << problems.size() << " messages need translating (README, \"Translating\"):\n"
        << problems.mid(0, 60).join(QLatin1Char('\n')).toStdString();
}

} // namespace translations_test
