package io.concord.agents.proto;

/** The yellow-pages service types and the verbs of the wheelchair agents. See docs/wheelchair-protocol.md. */
public final class Services {
    /** A door agent; name: the door's id; properties: kind, x, y. */
    public static final String DOOR = "wheelchair-door";
    /** A planner agent; property: chair (the control agent it plans for). */
    public static final String PLANNER = "wheelchair-planner";
    /** A control agent that takes patient transports; property: chair. */
    public static final String TRANSPORT = "wheelchair-transport";
    /** The traffic agent: grants chairs their routes node by node so that they never meet. */
    public static final String TRAFFIC = "wheelchair-traffic";
    /** The Medical agent: takes transport requests. */
    public static final String MEDICAL = "medical-transport";
    /** The ontology every wheelchair message carries. */
    public static final String ONTOLOGY = "concord-wheelchair";
    /** The language every wheelchair message's content is written in (FIPA-SL). */
    public static final String LANGUAGE = "fipa-sl";

    private Services() {
    }
}
