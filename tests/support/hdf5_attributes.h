#pragma once
// Reads HDF5 attributes back the way an outside reader would, for the tests that check what
// the exporter wrote: strings of either kind (the exporter writes fixed-length ones, which
// Octave and MATLAB need) and doubles. Missing attributes read as "<missing>" and NaN.

#include <QByteArray>
#include <QString>
#include <hdf5.h>

#include <cmath>

namespace nbtest {

struct StringAttribute {
    QString text = QStringLiteral("<missing>");
    bool variableLength = false;
};

inline StringAttribute readStringAttribute(hid_t obj, const char* name)
{
    StringAttribute out;
    const hid_t a = H5Aopen(obj, name, H5P_DEFAULT);
    if (a < 0)
        return out;
    out.text = QStringLiteral("<unreadable>");
    const hid_t stored = H5Aget_type(a);
    if (H5Tget_class(stored) == H5T_STRING && H5Tis_variable_str(stored) > 0) {
        out.variableLength = true;
        const hid_t t = H5Tcopy(H5T_C_S1);
        H5Tset_size(t, H5T_VARIABLE);
        H5Tset_cset(t, H5Tget_cset(stored));
        char* s = nullptr;
        if (H5Aread(a, t, &s) >= 0 && s)
            out.text = QString::fromUtf8(s);
        if (s)
            H5free_memory(s);
        H5Tclose(t);
    } else if (H5Tget_class(stored) == H5T_STRING) {
        QByteArray buffer(qsizetype(H5Tget_size(stored)), '\0');
        if (H5Aread(a, stored, buffer.data()) >= 0)
            out.text = QString::fromUtf8(buffer.constData(), qstrnlen(buffer.constData(), buffer.size()));
    }
    H5Tclose(stored);
    H5Aclose(a);
    return out;
}

inline double readDoubleAttribute(hid_t obj, const char* name)
{
    const hid_t a = H5Aopen(obj, name, H5P_DEFAULT);
    if (a < 0)
        return std::nan("");
    double v = std::nan("");
    H5Aread(a, H5T_NATIVE_DOUBLE, &v);
    H5Aclose(a);
    return v;
}

}  // namespace nbtest
