package io.concord.agents.map;

import java.util.List;

/**
 * A named region of the floor: a ward, a room in a ward, a corridor or a hall.
 *
 * @param id      unique id ("ward-a", "a-n1")
 * @param kind    what it is
 * @param name    what people call it ("Ward A", "Room 3")
 * @param ward    the id of the ward a room belongs to, or null
 * @param polygon its outline, at least three corners
 */
public record Area(String id, Kind kind, String name, String ward, List<Point> polygon) {

    /** The kinds of area. */
    public enum Kind { WARD, ROOM, CORRIDOR, HALL }

    /** Copies the outline. */
    public Area {
        polygon = List.copyOf(polygon);
    }

    /** True if the point lies inside the outline (even-odd rule). */
    public boolean contains(Point p) {
        boolean in = false;
        for (int i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
            Point a = polygon.get(i);
            Point b = polygon.get(j);
            if ((a.y() > p.y()) != (b.y() > p.y())
                    && p.x() < (b.x() - a.x()) * (p.y() - a.y()) / (b.y() - a.y()) + a.x()) {
                in = !in;
            }
        }
        return in;
    }
}
