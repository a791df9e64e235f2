package io.concord.core.proto;

/** The names of the FIPA interaction protocols, as they appear in {@code :protocol}. */
public final class FipaProtocols {
    public static final String REQUEST = "fipa-request";
    public static final String QUERY = "fipa-query";
    public static final String CONTRACT_NET = "fipa-contract-net";
    public static final String SUBSCRIBE = "fipa-subscribe";

    private FipaProtocols() {
    }
}
