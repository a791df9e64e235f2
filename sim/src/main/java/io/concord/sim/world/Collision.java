package io.concord.sim.world;

import io.concord.agents.map.Point;

/**
 * A chair touched something: a wall, a door leaf, another chair or an obstacle.
 *
 * @param timeNs world time
 * @param chair  the chair's name
 * @param other  what it touched: "wall", "door WA", a chair's or an obstacle's name
 * @param at     where
 */
public record Collision(long timeNs, String chair, String other, Point at) {
}
