package io.concord.agents.map;

import java.util.Locale;

/**
 * A point on the floor, in metres (x east, y north).
 *
 * @param x metres
 * @param y metres
 */
public record Point(double x, double y) {

    /** The distance in metres to another point. */
    public double distanceTo(Point o) {
        return Math.hypot(o.x - x, o.y - y);
    }

    @Override
    public String toString() {
        return String.format(Locale.ROOT, "(%s, %s)", trim(x), trim(y));
    }

    static String trim(double v) {
        String s = String.format(Locale.ROOT, "%.3f", v);
        s = s.replaceAll("0+$", "");
        return s.endsWith(".") ? s.substring(0, s.length() - 1) : s;
    }
}
