package io.concord.agents.map;

import java.util.List;

/**
 * A hospital map that cannot be used: malformed JSON, a missing or wrong field, or an
 * inconsistency (an edge to an unknown node, a door on no wall gap, overlapping nodes, a wall of
 * zero length, a node inside a wall, an edge through a wall...). Lists every problem found, each
 * naming the element and what is wrong. Nothing of such a map is loaded.
 */
public final class MapException extends IllegalArgumentException {
    private final String source;
    private final List<String> problems;

    /** A refusal of the map read from {@code source}, with its problems. */
    public MapException(String source, List<String> problems) {
        super(message(source, problems));
        this.source = source;
        this.problems = List.copyOf(problems);
    }

    private static String message(String source, List<String> problems) {
        StringBuilder b = new StringBuilder("hospital map ").append(source).append(" refused, ")
                .append(problems.size()).append(problems.size() == 1 ? " problem:" : " problems:");
        for (String p : problems) {
            b.append("\n  - ").append(p);
        }
        return b.toString();
    }

    /** Where the map came from (a path or a resource name). */
    public String source() {
        return source;
    }

    /** Each problem, naming the element. */
    public List<String> problems() {
        return problems;
    }
}
