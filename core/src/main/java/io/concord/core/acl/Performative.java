package io.concord.core.acl;

import java.util.HashMap;
import java.util.Locale;
import java.util.Map;

/** The 22 communicative acts of the FIPA Communicative Act Library (SC00037). */
public enum Performative {
    ACCEPT_PROPOSAL, AGREE, CANCEL, CFP, CONFIRM, DISCONFIRM, FAILURE, INFORM, INFORM_IF, INFORM_REF,
    NOT_UNDERSTOOD, PROPAGATE, PROPOSE, PROXY, QUERY_IF, QUERY_REF, REFUSE, REJECT_PROPOSAL, REQUEST,
    REQUEST_WHEN, REQUEST_WHENEVER, SUBSCRIBE;

    private static final Performative[] VALUES = values();
    private static final Map<String, Performative> BY_WIRE_NAME = new HashMap<>();

    static {
        for (Performative p : VALUES) {
            BY_WIRE_NAME.put(p.wireName, p);
        }
    }

    private final String wireName = name().replace('_', '-');

    /** The name as FIPA writes it, e.g. {@code QUERY-REF}. */
    public String wireName() {
        return wireName;
    }

    /**
     * Looks a performative up by its FIPA name in any case ({@code query-ref}, {@code QUERY-REF}).
     *
     * @return the performative, or {@code null} if the name is not one of the 22
     */
    public static Performative fromWireName(String name) {
        return BY_WIRE_NAME.get(name.toUpperCase(Locale.ROOT));
    }

    /** The performative with the given ordinal, as used by the binary codec; {@code null} if out of range. */
    public static Performative fromOrdinal(int ordinal) {
        return ordinal >= 0 && ordinal < VALUES.length ? VALUES[ordinal] : null;
    }
}
