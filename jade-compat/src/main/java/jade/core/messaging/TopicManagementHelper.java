package jade.core.messaging;

import jade.core.AID;
import jade.core.ServiceException;
import jade.core.ServiceHelper;

/**
 * JADE's topics: {@code getHelper(TopicManagementHelper.SERVICE_NAME)} gives one; a message sent
 * to a topic's AID goes to every agent registered for that topic (in this JVM here), and
 * {@code MessageTemplate.MatchTopic} picks it out. concord-jade always has it (JADE needs
 * {@code jade.core.messaging.TopicManagementService} in the profile's services).
 */
public interface TopicManagementHelper extends ServiceHelper {
    String SERVICE_NAME = "jade.core.messaging.TopicManagement";
    String TOPIC_SUFFIX = "TOPIC_";
    String TOPIC_TEMPLATE_WILDCARD = "*";

    /** The AID of the topic of that name ({@code name@TOPIC_}, as JADE names it). */
    AID createTopic(String topicName);

    boolean isTopic(AID id);

    /** Registers the agent itself for the topic. */
    void register(AID topic) throws ServiceException;

    /** Registers that agent (of this JVM) for the topic. */
    void register(AID aid, AID topic) throws ServiceException;

    void deregister(AID topic) throws ServiceException;

    void deregister(AID aid, AID topic) throws ServiceException;
}
