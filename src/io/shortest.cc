// The shortest decimal digits that read back to the same double (Google's double-conversion,
// Grisu3 with a bignum fallback): the one C++ file of the library, behind a C function
// (io_internal.h) that text.c turns into the writers' number format.
#include <double-conversion/double-to-string.h>

extern "C" int ori__shortest_digits(double x, char *digits, int *length, int *point);

extern "C" int ori__shortest_digits(double x, char *digits, int *length, int *point)
{
    bool sign = false;
    double_conversion::DoubleToStringConverter::DoubleToAscii(
        x, double_conversion::DoubleToStringConverter::SHORTEST, 0, digits,
        double_conversion::DoubleToStringConverter::kBase10MaximalLength + 1, &sign, length, point);
    return sign ? 1 : 0;
}
