package jade.domain.JADEAgentManagement;

import jade.content.onto.BasicOntology;
import jade.content.onto.Ontology;
import jade.content.onto.OntologyException;
import jade.content.schema.AgentActionSchema;
import jade.content.schema.ConceptSchema;
import jade.content.schema.ObjectSchema;
import jade.content.schema.PrimitiveSchema;
import jade.core.ContainerID;

/**
 * JADE's agent-management ontology, for the actions concord-jade's AMS carries out:
 * {@link CreateAgent}, {@link KillAgent}, {@link QueryAgentsOnLocation}, {@link ShutdownPlatform}
 * (and {@code container-ID}). Send them to {@code getAMS()} in a REQUEST (language FIPA-SL, this
 * ontology), as {@code Action(getAMS(), action)}; the AMS answers INFORM (or FAILURE,
 * NOT_UNDERSTOOD). JADE's other management actions (containers, MTPs, sniffing, ...) are not here.
 */
public class JADEManagementOntology extends Ontology implements JADEManagementVocabulary {
    private static final long serialVersionUID = 1L;
    private static final Ontology INSTANCE = new JADEManagementOntology();

    public static Ontology getInstance() {
        return INSTANCE;
    }

    private JADEManagementOntology() {
        super(NAME, BasicOntology.getInstance());
        try {
            PrimitiveSchema string = (PrimitiveSchema) getSchema(BasicOntology.STRING);
            ConceptSchema container = new ConceptSchema(CONTAINERID);
            add(container, ContainerID.class);
            container.add(CONTAINERID_NAME, string);
            container.add(CONTAINERID_ADDRESS, string, ObjectSchema.OPTIONAL);

            AgentActionSchema kill = new AgentActionSchema(KILLAGENT);
            add(kill, KillAgent.class);
            kill.add(KILLAGENT_AGENT, (ConceptSchema) getSchema(BasicOntology.AID));
            kill.add(KILLAGENT_PASSWORD, string, ObjectSchema.OPTIONAL);

            AgentActionSchema create = new AgentActionSchema(CREATEAGENT);
            add(create, CreateAgent.class);
            create.add(CREATEAGENT_AGENT_NAME, string);
            create.add(CREATEAGENT_CLASS_NAME, string);
            create.add(CREATEAGENT_ARGUMENTS, string, 0, ObjectSchema.UNLIMITED);
            create.add(CREATEAGENT_CONTAINER, container);

            add(new AgentActionSchema(SHUTDOWNPLATFORM), ShutdownPlatform.class);

            AgentActionSchema query = new AgentActionSchema(QUERYAGENTSONLOCATION);
            add(query, QueryAgentsOnLocation.class);
            query.add(QUERYAGENTSONLOCATION_LOCATION, container);
        } catch (OntologyException e) {
            throw new IllegalStateException("the JADE management ontology does not build: " + e, e);
        }
    }
}
