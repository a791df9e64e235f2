package io.concord.layers.platform;

import io.concord.layers.parser.Membership;

/**
 * The words of the platform protocol every role, the directory, the relay and the federation
 * write: platform messages are FIPA ACL with this ontology and language, and each part of the
 * protocol has its own {@code :protocol} (see {@code docs/wire-format.md}).
 */
final class Protocol {
    static final String ONTOLOGY = Membership.PLATFORM_ONTOLOGY;
    static final String LANGUAGE = "concord-lines";
    static final String P_DISCOVERY = "concord-discovery";
    static final String P_LAL = "concord-lal";
    static final String P_MAINTENANCE = "concord-maintenance";
    static final String P_SERVICES = "concord-services";
    /** Between the containers of different hosts. */
    static final String P_NETWORK = "concord-network";

    private Protocol() {
    }
}
