import jade.core.AID;
import jade.core.Agent;
import jade.core.ServiceException;
import jade.core.behaviours.OneShotBehaviour;
import jade.core.messaging.TopicManagementHelper;
import jade.lang.acl.ACLMessage;
import jade.lang.acl.MessageTemplate;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;

/** Waits for two readers, posts two items on the topic "news", and prints what the readers read. */
public class Writer extends Agent {
    @Override
    protected void setup() {
        addBehaviour(new OneShotBehaviour(this) {
            @Override
            public void action() {
                try {
                    TopicManagementHelper topics = (TopicManagementHelper) getHelper(TopicManagementHelper.SERVICE_NAME);
                    AID news = topics.createTopic("news");
                    System.out.println("topic " + news.getLocalName() + " is a topic: " + topics.isTopic(news)
                            + ", the writer is not: " + topics.isTopic(getAID()));
                    for (int i = 0; i < 2; i++) {
                        myAgent.blockingReceive(MessageTemplate.MatchContent("ready"));
                    }
                    for (String item : new String[] {"rain", "sun"}) {
                        ACLMessage m = new ACLMessage(ACLMessage.INFORM);
                        m.addReceiver(news);
                        m.setContent(item);
                        myAgent.send(m);
                        List<String> read = new ArrayList<>();
                        for (int i = 0; i < 2; i++) {
                            read.add(myAgent.blockingReceive(MessageTemplate.MatchPerformative(ACLMessage.CONFIRM)).getContent());
                        }
                        Collections.sort(read);
                        System.out.println(read);
                    }
                } catch (ServiceException e) {
                    System.out.println("writer: no topics: " + e.getMessage());
                }
                myAgent.doDelete();
            }
        });
    }

    @Override
    protected void takeDown() {
        System.exit(0);
    }
}
