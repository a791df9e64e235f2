package jade.domain.FIPAAgentManagement;

import jade.content.onto.BasicOntology;
import jade.content.onto.Ontology;
import jade.content.onto.OntologyException;
import jade.content.schema.AgentActionSchema;
import jade.content.schema.ConceptSchema;
import jade.content.schema.ObjectSchema;
import jade.content.schema.PrimitiveSchema;
import jade.content.schema.TermSchema;

/**
 * FIPA's agent-management ontology ({@code FIPA-Agent-Management}) as JADE 4.3 names it: the
 * concepts {@code df-agent-description}, {@code service-description}, {@code property},
 * {@code search-constraints} (JADE's classes of this package) and the actions {@code register},
 * {@code deregister}, {@code modify}, {@code search} (written by position, as JADE writes them) and
 * {@code get-description}; slots in JADE's order. Not here: {@code ams-agent-description},
 * {@code ap-description}, {@code ap-service} and the exception predicates.
 */
public class FIPAManagementOntology extends Ontology implements FIPAManagementVocabulary {
    private static final long serialVersionUID = 1L;
    private static final FIPAManagementOntology INSTANCE = new FIPAManagementOntology();

    private FIPAManagementOntology() {
        super(NAME, BasicOntology.getInstance());
        try {
            PrimitiveSchema string = (PrimitiveSchema) getSchema(BasicOntology.STRING);
            PrimitiveSchema integer = (PrimitiveSchema) getSchema(BasicOntology.INTEGER);
            ConceptSchema aid = (ConceptSchema) getSchema(BasicOntology.AID);
            TermSchema any = (TermSchema) TermSchema.getBaseSchema();

            ConceptSchema property = new ConceptSchema(PROPERTY);
            property.add(PROPERTY_NAME, string);
            property.add(PROPERTY_VALUE, any, ObjectSchema.OPTIONAL);
            add(property, Property.class);

            ConceptSchema service = new ConceptSchema(SERVICEDESCRIPTION);
            service.add(SERVICEDESCRIPTION_NAME, string, ObjectSchema.OPTIONAL);
            service.add(SERVICEDESCRIPTION_TYPE, string, ObjectSchema.OPTIONAL);
            service.add(SERVICEDESCRIPTION_OWNERSHIP, string, ObjectSchema.OPTIONAL);
            service.add(SERVICEDESCRIPTION_PROTOCOLS, string, 0, ObjectSchema.UNLIMITED, BasicOntology.SET);
            service.add(SERVICEDESCRIPTION_LANGUAGES, string, 0, ObjectSchema.UNLIMITED, BasicOntology.SET);
            service.add(SERVICEDESCRIPTION_ONTOLOGIES, string, 0, ObjectSchema.UNLIMITED, BasicOntology.SET);
            service.add(SERVICEDESCRIPTION_PROPERTIES, property, 0, ObjectSchema.UNLIMITED, BasicOntology.SET);
            add(service, ServiceDescription.class);

            ConceptSchema dfd = new ConceptSchema(DFAGENTDESCRIPTION);
            dfd.add(DFAGENTDESCRIPTION_NAME, aid, ObjectSchema.OPTIONAL);
            dfd.add(DFAGENTDESCRIPTION_SERVICES, service, 0, ObjectSchema.UNLIMITED, BasicOntology.SET);
            dfd.add(DFAGENTDESCRIPTION_PROTOCOLS, string, 0, ObjectSchema.UNLIMITED, BasicOntology.SET);
            dfd.add(DFAGENTDESCRIPTION_LANGUAGES, string, 0, ObjectSchema.UNLIMITED, BasicOntology.SET);
            dfd.add(DFAGENTDESCRIPTION_ONTOLOGIES, string, 0, ObjectSchema.UNLIMITED, BasicOntology.SET);
            dfd.add(DFAGENTDESCRIPTION_LEASE_TIME, (PrimitiveSchema) getSchema(BasicOntology.DATE), ObjectSchema.OPTIONAL);
            add(dfd, DFAgentDescription.class);

            ConceptSchema constraints = new ConceptSchema(SEARCHCONSTRAINTS);
            constraints.add(SEARCHCONSTRAINTS_MAX_DEPTH, integer, ObjectSchema.OPTIONAL);
            constraints.add(SEARCHCONSTRAINTS_MAX_RESULTS, integer, ObjectSchema.OPTIONAL);
            constraints.add(SEARCHCONSTRAINTS_SEARCH_ID, string, ObjectSchema.OPTIONAL);
            add(constraints, SearchConstraints.class);

            add(action(REGISTER, REGISTER_DESCRIPTION, any), Register.class);
            add(action(DEREGISTER, DEREGISTER_DESCRIPTION, any), Deregister.class);
            add(action(MODIFY, MODIFY_DESCRIPTION, any), Modify.class);
            AgentActionSchema search = action(SEARCH, SEARCH_DESCRIPTION, any);
            search.add(SEARCH_CONSTRAINTS, constraints);
            add(search, Search.class);
            add(new AgentActionSchema(GETDESCRIPTION), GetDescription.class);
        } catch (OntologyException e) {
            throw new IllegalStateException(e);
        }
    }

    private static AgentActionSchema action(String name, String slot, TermSchema description) {
        AgentActionSchema s = new AgentActionSchema(name);
        s.add(slot, description);
        s.setEncodingByOrder(true);
        return s;
    }

    /** The one instance. */
    public static Ontology getInstance() {
        return INSTANCE;
    }
}
