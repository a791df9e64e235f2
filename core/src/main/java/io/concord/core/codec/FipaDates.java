package io.concord.core.codec;

import io.concord.core.acl.FipaStringWriter;
import io.concord.core.time.Clock;

import java.time.DateTimeException;
import java.time.Instant;
import java.time.LocalDateTime;
import java.time.ZoneId;
import java.time.ZoneOffset;
import java.time.ZonedDateTime;
import java.time.format.DateTimeFormatter;
import java.util.Calendar;
import java.util.GregorianCalendar;
import java.util.TimeZone;

/**
 * FIPA date-times ({@code YYYYMMDDThhmmssSSS}, SC00070): absolute in UTC with a trailing
 * {@code Z}, absolute in local time without it (as JADE reads them), or relative to now with a
 * leading {@code +}.
 *
 * <p>The calendar is JADE's ({@link GregorianCalendar}): Gregorian from 15 October 1582, Julian
 * before, so a date JADE writes for an instant before 1582 is read as the same instant, and the
 * other way round. Years run from 1 to 9999, the four digits the format has.
 */
final class FipaDates {
    private static final DateTimeFormatter UTC =
            DateTimeFormatter.ofPattern("uuuuMMdd'T'HHmmssSSS'Z'").withZone(ZoneOffset.UTC);
    /** 1582-10-15T00:00Z, the first instant of the Gregorian calendar (from here on java.time agrees). */
    static final long GREGORIAN_CUTOVER_MS = -12219292800000L;
    /** 10000-01-01T00:00Z: from here the year needs five digits. */
    private static final long YEAR_10000_MS = 253402300800000L;

    private FipaDates() {
    }

    /**
     * Formats epoch milliseconds as {@code YYYYMMDDThhmmssSSSZ} in UTC.
     *
     * @throws IllegalArgumentException if the instant is outside the years 1 to 9999
     */
    public static String format(long epochMs) {
        return FipaStringWriter.formatDate(epochMs);
    }

    /**
     * As {@link #format}, but never refuses: an instant outside the years 1 to 9999 is written with
     * java.time's signed year of more or fewer digits (which FIPA's format cannot hold, so no reader
     * takes it back), for logs and for messages that never leave Concord.
     */
    public static String formatAnyYear(long epochMs) {
        return FipaStringWriter.formatDateAnyYear(epochMs);
    }

    /**
     * Parses a FIPA date-time.
     *
     * @param at    where the value started in the input, for the error
     * @param clock the time relative values count from
     */
    static long parse(String v, int at, Clock clock) throws AclParseException {
        String t = v;
        boolean relative = false;
        if (t.startsWith("+") || t.startsWith("-")) {
            relative = t.charAt(0) == '+';
            if (!relative) {
                throw new AclParseException(at, "a FIPA date-time YYYYMMDDThhmmssSSS[Z] or +YYYYMMDDThhmmssSSS",
                        "'" + v + "' (a negative relative time)");
            }
            t = t.substring(1);
        }
        boolean utc = t.endsWith("Z") || t.endsWith("z");
        if (utc) {
            t = t.substring(0, t.length() - 1);
        }
        // YYYYMMDD T hhmmss SSS; JADE ignores the 9th character, so accept any there.
        if (t.length() != 18) {
            throw new AclParseException(at, "a FIPA date-time YYYYMMDDThhmmssSSS[Z]", "'" + v + "'");
        }
        int[] f = new int[7];
        int[][] spans = {{0, 4}, {4, 6}, {6, 8}, {9, 11}, {11, 13}, {13, 15}, {15, 18}};
        for (int i = 0; i < spans.length; i++) {
            String part = t.substring(spans[i][0], spans[i][1]);
            for (int k = 0; k < part.length(); k++) {
                if (part.charAt(k) < '0' || part.charAt(k) > '9') {
                    throw new AclParseException(at + spans[i][0], "a digit in the FIPA date-time", "'" + v + "'");
                }
            }
            f[i] = Integer.parseInt(part);
        }
        try {
            if (relative) {
                ZonedDateTime now = Instant.ofEpochMilli(clock.epochMillis()).atZone(ZoneOffset.UTC);
                return now.plusYears(f[0]).plusMonths(f[1]).plusDays(f[2]).plusHours(f[3]).plusMinutes(f[4])
                        .plusSeconds(f[5]).plusNanos(f[6] * 1_000_000L).toInstant().toEpochMilli();
            }
            if (f[0] > 1582 || (f[0] == 1582 && (f[1] > 10 || (f[1] == 10 && f[2] >= 15)))) {
                LocalDateTime ldt = LocalDateTime.of(f[0], f[1], f[2], f[3], f[4], f[5], f[6] * 1_000_000);
                ZoneId zone = utc ? ZoneOffset.UTC : ZoneId.systemDefault();
                return ldt.atZone(zone).toInstant().toEpochMilli();
            }
            return julian(f, utc);
        } catch (DateTimeException | ArithmeticException | IllegalArgumentException e) {
            throw new AclParseException(at, "a valid calendar date-time", "'" + v + "' (" + e.getMessage() + ")");
        }
    }

    /** A date before 15 October 1582, in the Julian calendar as JADE's GregorianCalendar reads it. */
    private static long julian(int[] f, boolean utc) {
        if (f[0] < 1) {
            throw new IllegalArgumentException("the year 0 does not exist; years run from 0001");
        }
        if (f[0] == 1582 && f[1] == 10 && f[2] > 4) {
            throw new IllegalArgumentException("4 October 1582 (Julian) was followed by 15 October (Gregorian)");
        }
        GregorianCalendar c = new GregorianCalendar(utc ? TimeZone.getTimeZone("UTC") : TimeZone.getDefault());
        c.setLenient(false);
        c.clear();
        c.set(f[0], f[1] - 1, f[2], f[3], f[4], f[5]);
        c.set(Calendar.MILLISECOND, f[6]);
        return c.getTimeInMillis();
    }
}
