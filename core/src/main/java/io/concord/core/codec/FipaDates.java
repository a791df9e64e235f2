package io.concord.core.codec;

import io.concord.core.time.Clock;

import java.time.LocalDateTime;
import java.time.ZoneId;
import java.time.ZoneOffset;
import java.time.ZonedDateTime;
import java.time.format.DateTimeFormatter;

/**
 * FIPA date-times ({@code YYYYMMDDThhmmssSSS}, SC00070): absolute in UTC with a trailing
 * {@code Z}, absolute in local time without it (as JADE reads them), or relative to now with a
 * leading {@code +}.
 */
public final class FipaDates {
    private static final DateTimeFormatter UTC =
            DateTimeFormatter.ofPattern("uuuuMMdd'T'HHmmssSSS'Z'").withZone(ZoneOffset.UTC);

    private FipaDates() {
    }

    /** Formats epoch milliseconds as {@code YYYYMMDDThhmmssSSSZ} in UTC. */
    public static String format(long epochMs) {
        return UTC.format(java.time.Instant.ofEpochMilli(epochMs));
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
                ZonedDateTime now = java.time.Instant.ofEpochMilli(clock.epochMillis()).atZone(ZoneOffset.UTC);
                return now.plusYears(f[0]).plusMonths(f[1]).plusDays(f[2]).plusHours(f[3]).plusMinutes(f[4])
                        .plusSeconds(f[5]).plusNanos(f[6] * 1_000_000L).toInstant().toEpochMilli();
            }
            LocalDateTime ldt = LocalDateTime.of(f[0], f[1], f[2], f[3], f[4], f[5], f[6] * 1_000_000);
            ZoneId zone = utc ? ZoneOffset.UTC : ZoneId.systemDefault();
            return ldt.atZone(zone).toInstant().toEpochMilli();
        } catch (java.time.DateTimeException | ArithmeticException e) {
            throw new AclParseException(at, "a valid calendar date-time", "'" + v + "' (" + e.getMessage() + ")");
        }
    }
}
