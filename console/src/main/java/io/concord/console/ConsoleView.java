package io.concord.console;

import java.util.List;
import java.util.Map;

/**
 * A view an application adds to the console (the hospital adds its map). Its snapshot is taken on
 * the agents' loop every {@link #periodMs()} while a browser shows it, and sent as one event; its
 * actions, with the console's own (start, kill, send), are its only writes, allowed on loopback or with the token.
 */
public interface ConsoleView {

    /** A short id, used in URLs and event names: letters, digits and {@code -}. */
    String id();

    /** The tab's title. */
    String title();

    /** How often a browser showing it gets a new snapshot. */
    default long periodMs() {
        return 250;
    }

    /** The state to draw, as one JSON object. Called on the agents' loop. */
    String snapshot();

    /**
     * The parameter the console adds to every action's: the address of the browser that asked
     * ({@code 127.0.0.1:53122}), for an audit trail. A browser's own value for it is replaced.
     */
    String CLIENT = "console.client";

    /** The actions a browser may ask for ({@code "transport"}); none by default. */
    default List<String> actions() {
        return List.of();
    }

    /**
     * Carries out an action on the agents' loop; returns what to tell the user.
     *
     * @throws IllegalArgumentException saying which parameter is wrong (the browser gets 400)
     */
    default String act(String action, Map<String, String> params) {
        throw new IllegalArgumentException("the view " + id() + " has no action " + action);
    }
}
