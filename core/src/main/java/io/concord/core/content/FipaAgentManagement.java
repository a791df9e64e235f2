package io.concord.core.content;

import io.concord.core.acl.AID;

import java.time.Instant;
import java.util.Set;

/**
 * The FIPA agent-management ontology (FIPA SC00023, {@code FIPA-Agent-Management}) as far as a
 * platform's DF and AMS use it: the descriptions (df-agent-description, service-description,
 * property, search-constraints, ams-agent-description) and the actions register, deregister,
 * modify, search and get-description. Schema and slot names are FIPA's (and JADE 4.3's
 * {@code FIPAManagementOntology}'s); the actions are written by position, as JADE writes them:
 * {@code (search (df-agent-description ...) (search-constraints :max-results -1))}.
 * Answers use the basic ontology: {@link Done} of the action, or {@link Result} with a list of
 * descriptions.
 */
public final class FipaAgentManagement {
    /** The ontology's name, for the {@code :ontology} slot. */
    public static final String NAME = "FIPA-Agent-Management";

    private static final BeanOntology INSTANCE = new BeanOntology(NAME, Property.class, ServiceDescription.class,
            DfAgentDescription.class, SearchConstraints.class, AmsAgentDescription.class, Register.class,
            Deregister.class, Modify.class, Search.class, GetDescription.class);

    private FipaAgentManagement() {
    }

    /** The ontology (immutable, shared). */
    public static BeanOntology ontology() {
        return INSTANCE;
    }

    /** A property of a service: a name and any value. */
    @Element(name = "property")
    public record Property(@Slot(mandatory = true) String name, Object value) implements Concept {
    }

    /** A service an agent offers. */
    @Element(name = "service-description")
    public record ServiceDescription(String name, String type, String ownership, Set<String> protocols,
                                     Set<String> languages, Set<String> ontologies, Set<Property> properties)
            implements Concept {
    }

    /** An agent's entry in a DF, or a template to search with (every slot optional). */
    @Element(name = "df-agent-description")
    public record DfAgentDescription(AID name, Set<ServiceDescription> services, Set<String> protocols,
                                     Set<String> languages, Set<String> ontologies,
                                     @Slot(name = "lease-time") Instant leaseTime) implements Concept {
    }

    /** How far a search goes; -1 results for no limit. */
    @Element(name = "search-constraints")
    public record SearchConstraints(@Slot(name = "max-depth") Long maxDepth, @Slot(name = "max-results") Long maxResults,
                                    @Slot(name = "search-id") String searchId) implements Concept {
    }

    /** An agent's entry in the AMS. */
    @Element(name = "ams-agent-description")
    public record AmsAgentDescription(AID name, String ownership, String state) implements Concept {
    }

    /** Register a description (a df-agent-description with the DF, an ams-agent-description with the AMS). */
    @Element(name = "register")
    public record Register(@Slot(position = 0, mandatory = true) Object description) implements AgentAction {
    }

    /** Deregister a description. */
    @Element(name = "deregister")
    public record Deregister(@Slot(position = 0, mandatory = true) Object description) implements AgentAction {
    }

    /** Replace a registered description. */
    @Element(name = "modify")
    public record Modify(@Slot(position = 0, mandatory = true) Object description) implements AgentAction {
    }

    /** Search for descriptions matching a template. */
    @Element(name = "search")
    public record Search(@Slot(position = 0, mandatory = true) Object description,
                         @Slot(position = 1, mandatory = true) SearchConstraints constraints) implements AgentAction {
    }

    /** Ask the AMS for the platform's description. */
    @Element(name = "get-description")
    public record GetDescription() implements AgentAction {
    }
}
