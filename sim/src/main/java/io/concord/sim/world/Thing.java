package io.concord.sim.world;

/** What a physics body is, kept as its user data. */
final class Thing {
    enum Kind { WALL, LEAF, CHAIR, OBSTACLE }

    static final int WALL_BIT = 1;
    static final int LEAF_BIT = 2;
    static final int CHAIR_BIT = 4;
    static final int OBSTACLE_BIT = 8;

    final Kind kind;
    final String name;
    final Object owner;

    Thing(Kind kind, String name, Object owner) {
        this.kind = kind;
        this.name = name;
        this.owner = owner;
    }

    /** Something a door stops for and a doorway sees: a chair or an obstacle. */
    boolean isSolidMover() {
        return kind == Kind.CHAIR || kind == Kind.OBSTACLE;
    }
}
