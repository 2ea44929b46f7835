#include "excerpt.h"

#include "core/tr.h"

namespace nb {

QString excerpt(QStringView text, int max_chars)
{
    QString out;
    const qsizetype n = text.size();
    qsizetype i = 0;
    int shown = 0;
    for (; i < n && shown < max_chars; ++i, ++shown) {
        const QChar c = text[i];
        const char16_t u = c.unicode();
        if (u == '\n')
            out += QLatin1String("\\n");
        else if (u == '\r')
            out += QLatin1String("\\r");
        else if (u == '\t')
            out += QLatin1String("\\t");
        else if (u < 0x20 || u == 0x7f)
            out += QStringLiteral("\\x%1").arg(int(u), 2, 16, QLatin1Char('0'));
        else if (c.category() == QChar::Other_Control || c.category() == QChar::Other_Format ||
                 u == 0x2028 || u == 0x2029)
            out += QStringLiteral("\\u{%1}").arg(int(u), 4, 16, QLatin1Char('0'));
        else
            out += c;
    }
    if (i < n)
        out += nb::TrCore::tr("… (%n more characters)", nullptr, int(std::min<qsizetype>(n - i, 1 << 30)));
    return out;
}

QString excerpt(const QByteArray& utf8, int max_chars)
{
    // Decode no more than a few characters' worth: the excerpt of a huge field stays cheap.
    const qsizetype take = std::min<qsizetype>(utf8.size(), qsizetype(max_chars) * 4 + 4);
    QString head = QString::fromUtf8(utf8.constData(), take);
    if (take < utf8.size()) {
        // The count of what was left out is in bytes here; say so plainly.
        QString out = excerpt(QStringView(head).left(max_chars), max_chars);
        return out + nb::TrCore::tr("… (%1 bytes in all)").arg(utf8.size());
    }
    return excerpt(QStringView(head), max_chars);
}

}  // namespace nb
