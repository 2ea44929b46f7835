#pragma once
// What a message may quote of its input: a short excerpt with control characters escaped, so
// that a 10 MB field or raw escape sequences in a file never reach the terminal or a log whole.

#include <QString>
#include <QStringView>

namespace nb {

// At most `max_chars` characters of `text` (then "…" and how many were left out), with
// control characters written as \n, \r, \t or \xNN / \u{NNNN}.
QString excerpt(QStringView text, int max_chars = 60);
QString excerpt(const QByteArray& utf8, int max_chars = 60);

}  // namespace nb
