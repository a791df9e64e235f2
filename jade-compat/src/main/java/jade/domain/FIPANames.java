package jade.domain;

/** FIPA's names: agents, protocols, content languages, ontologies. */
public interface FIPANames {
    String AMS = "ams";
    String DEFAULT_DF = "df";

    /** Interaction protocols. */
    interface InteractionProtocol {
        String FIPA_REQUEST = "fipa-request";
        String FIPA_QUERY = "fipa-query";
        String FIPA_REQUEST_WHEN = "fipa-request-when";
        String FIPA_BROKERING = "fipa-brokering";
        String FIPA_RECRUITING = "fipa-recruiting";
        String FIPA_PROPOSE = "fipa-propose";
        String FIPA_SUBSCRIBE = "fipa-subscribe";
        String FIPA_ENGLISH_AUCTION = "fipa-auction-english";
        String FIPA_DUTCH_AUCTION = "fipa-auction-dutch";
        String FIPA_CONTRACT_NET = "fipa-contract-net";
        String FIPA_ITERATED_CONTRACT_NET = "fipa-iterated-contract-net";
        String ITERATED_FIPA_REQUEST = "iterated-fipa-request";
    }

    /** Content languages. */
    interface ContentLanguage {
        String FIPA_SL0 = "fipa-sl0";
        String FIPA_SL1 = "fipa-sl1";
        String FIPA_SL2 = "fipa-sl2";
        String FIPA_SL = "fipa-sl";
    }

    /** Ontologies. */
    interface Ontology {
        String SL0_ONTOLOGY = "FIPA-Agent-Management";
    }
}
