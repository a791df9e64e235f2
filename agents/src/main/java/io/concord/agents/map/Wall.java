package io.concord.agents.map;

/**
 * A straight wall: its centre line from one point to another, and its thickness.
 *
 * @param id         the wall's name in the map ("w12"), for messages
 * @param from       one end of the centre line
 * @param to         the other end
 * @param thicknessM metres
 */
public record Wall(String id, Point from, Point to, double thicknessM) {

    /** Length of the centre line, metres. */
    public double length() {
        return from.distanceTo(to);
    }
}
