package io.concord.jadecompat.internal;

/** What the content mapping needs of a JADE-named schema beyond JADE's public accessors. */
public interface SlotFacets {
    /** The fewest elements of an aggregate slot (0 for any other). */
    int cardMin(String slot);

    /** The most elements of an aggregate slot, -1 for no limit. */
    int cardMax(String slot);
}
