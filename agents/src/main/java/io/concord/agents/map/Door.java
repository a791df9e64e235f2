package io.concord.agents.map;

/**
 * A door in a gap of the walls. Its opening runs from one jamb ({@code from}) to the other
 * ({@code to}); the leaf fills it when closed.
 *
 * <ul>
 *   <li>{@link Kind#HINGED}: one leaf on hinges at the jamb {@code hinge} names, swinging a
 *       quarter turn to the {@code swing} side of the line from {@code from} to {@code to}.</li>
 *   <li>{@link Kind#SLIDING}: one leaf that slides along the wall, past the jamb {@code hinge}
 *       names, into a pocket in the wall.</li>
 *   <li>{@link Kind#ROTATING}: a revolving leaf on a pivot in the middle of the opening: a
 *       quarter turn opens it (two lanes, one each side of the pivot), the next quarter turn the
 *       same way closes it.</li>
 * </ul>
 *
 * @param id    unique id ("D3")
 * @param kind  hinged, sliding or rotating
 * @param from  one jamb
 * @param to    the other jamb
 * @param hinge for a hinged door the jamb with the hinges, for a sliding one the jamb the leaf
 *              slides past; unused for a rotating door
 * @param swing for a hinged door the side it opens to, looking from {@code from} to {@code to}
 */
public record Door(String id, Kind kind, Point from, Point to, End hinge, Side swing) {

    /** The three kinds of door of the dissertation's hospital. */
    public enum Kind { HINGED, SLIDING, ROTATING }

    /** A jamb of the opening. */
    public enum End { FROM, TO }

    /** A side of the opening, looking from {@code from} to {@code to}. */
    public enum Side { LEFT, RIGHT }

    /** Width of the opening, metres. */
    public double width() {
        return from.distanceTo(to);
    }

    /** The middle of the opening. */
    public Point centre() {
        return new Point((from.x() + to.x()) / 2, (from.y() + to.y()) / 2);
    }

    /** The jamb the hinge (or slide) is at. */
    public Point hingePoint() {
        return hinge == End.TO ? to : from;
    }

    /** The other jamb. */
    public Point freePoint() {
        return hinge == End.TO ? from : to;
    }

    /** True if {@code p} is on the side of the opening its hinged leaf swings to (never for the other kinds). */
    public boolean onSwingSide(Point p) {
        if (kind != Kind.HINGED) {
            return false;
        }
        double cross = (to.x() - from.x()) * (p.y() - from.y()) - (to.y() - from.y()) * (p.x() - from.x());
        return swing == Side.LEFT ? cross > 0 : cross < 0;
    }

    /**
     * How far from the opening's centre, on the line across it, a body must stay on {@code p}'s side
     * so that the moving leaf passes {@code reach} metres clear of its centre: a hinged leaf sweeps a
     * quarter circle of the opening's width about its hinge (on its swing side only), a revolving one
     * a circle of half the width about its pivot, a sliding one only the wall's line (0).
     */
    public double clearDistance(Point p, double reach) {
        double w = width();
        return switch (kind) {
            case HINGED -> onSwingSide(p) ? Math.sqrt((w + reach) * (w + reach) - (w / 2) * (w / 2)) : 0;
            case ROTATING -> w / 2 + reach;
            case SLIDING -> 0;
        };
    }
}
